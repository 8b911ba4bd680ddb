// EXPECT: units of a duration literal must appear once each from highest to lowest
// IEC: units are written from days down to nanoseconds (t#4ms13d is an error).
#include <iecoop/iecoop.hpp>

using namespace iecoop;
#ifdef IECOOP_COMPILE_FAIL
constexpr TIME t = "t#4ms13d"_iec;
#else
constexpr TIME t = "t#13d4ms"_iec;
#endif
static_assert(t.count() > 0);
