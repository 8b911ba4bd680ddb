// EXPECT: negative value for an unsigned type
// TIME and LTIME are unsigned in CODESYS, so a negative duration literal is rejected.
#include <iecoop/iecoop.hpp>

using namespace iecoop;
#ifdef IECOOP_COMPILE_FAIL
constexpr auto t = "T#-5s"_iec;
#else
constexpr auto t = "T#5s"_iec;
#endif
static_assert(t.count() > 0);
