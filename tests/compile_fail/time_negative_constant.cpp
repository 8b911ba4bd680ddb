// EXPECT: duration constant out of range
// An integer constant given as a TIME counts milliseconds and must not be negative.
#include <iecoop/iecoop.hpp>

using namespace iecoop;
#ifdef IECOOP_COMPILE_FAIL
constexpr TIME pt = -300;
#else
constexpr TIME pt = 300;
#endif
static_assert(pt.count() == 300);
