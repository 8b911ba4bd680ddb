// iecoop-check fixture: includes shared_block.hpp (see there).
#include "shared_block.hpp"

inline iecoop::INT use_b(shared::FB_Shared& fb) { return fb.Value(); }
