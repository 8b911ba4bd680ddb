// EXPECT: no such date: the month is 1..12 and the day within the month
// 2100 is divisible by 100 but not by 400: no leap year, February has 28 days.
#include <iecoop/iecoop.hpp>

using namespace iecoop;
#ifdef IECOOP_COMPILE_FAIL
constexpr DATE d = "D#2100-02-29"_iec;
#else
constexpr DATE d = "D#2000-02-29"_iec;
#endif
static_assert(d.count() > 0);
