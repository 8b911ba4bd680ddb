// EXPECT: only the highest unit of a duration literal may overflow
// IEC: in a duration literal only the first (highest) unit may exceed its range; 68 s
// below a minutes unit is an error, T#100s12ms is fine.
#include <iecoop/iecoop.hpp>

using namespace iecoop;
#ifdef IECOOP_COMPILE_FAIL
constexpr TIME t = "t#5m68s"_iec;
#else
constexpr TIME t = "t#5m8s"_iec;
static_assert("T#100s12ms"_iec.count() == 100012);
#endif
static_assert(t.count() > 0);
