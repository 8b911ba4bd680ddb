// iecoop-check fixture: includes shared_block.hpp (see there).
#include "shared_block.hpp"

inline iecoop::INT use_a(shared::FB_SharedChild& fb) { return fb.Value(); }
