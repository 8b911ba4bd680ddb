// EXPECT: no such time of day: the hour is 0..23
// A time of day ends at TOD#23:59:59.999; TOD#24:00:00 is no literal.
#include <iecoop/iecoop.hpp>

using namespace iecoop;
#ifdef IECOOP_COMPILE_FAIL
constexpr TOD t = "TOD#24:00:00"_iec;
#else
constexpr TOD t = "TOD#23:59:59.999"_iec;
#endif
static_assert(t.count() > 0);
