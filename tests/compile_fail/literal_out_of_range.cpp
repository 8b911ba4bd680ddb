// EXPECT: the literal's value does not fit its type
// TIME is 32-bit milliseconds: at most T#49d17h2m47s295ms.
#include <iecoop/iecoop.hpp>

using namespace iecoop;
#ifdef IECOOP_COMPILE_FAIL
constexpr auto t = "T#50d"_iec;
#else
constexpr auto t = "LTIME#50d"_iec;
#endif
static_assert(t.count() > 0);
