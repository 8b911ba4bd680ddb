// EXPECT: only the highest unit of a duration literal may overflow
// EXPECT: spelled<'t', '#', '5', 'm', '6', '8', 's'>
// EXPECT: spelled<'T', '#', '6', 'm', '8', 's'>
// EXPECT-ERRORS: 1
// IEC: in a duration literal only the first (highest) unit may exceed its range; 68 s
// below a minutes unit is an error, T#100s12ms is fine. The error spells the user's literal
// and the same duration written as IEC allows.
#include <iecoop/iecoop.hpp>

using namespace iecoop;
int main() {
#ifdef IECOOP_COMPILE_FAIL
  constexpr TIME t = "t#5m68s"_iec;
#else
  constexpr TIME t = "t#6m8s"_iec;
  static_assert("T#100s12ms"_iec.count() == 100012);
#endif
  return t.count() == 368000 ? 0 : 1;
}
