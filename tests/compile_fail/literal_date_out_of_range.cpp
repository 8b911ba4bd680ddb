// EXPECT: the date is outside its type's range
// DATE is 32-bit seconds since 1970: its last day is D#2106-02-07; LDATE reaches 2554.
#include <iecoop/iecoop.hpp>

using namespace iecoop;
#ifdef IECOOP_COMPILE_FAIL
constexpr DATE d = "D#2106-02-08"_iec;
#else
constexpr LDATE d = "LDATE#2106-02-08"_iec;
#endif
static_assert(d.count() > 0);
