// EXPECT: unknown unit in a duration literal
// EXPECT-ERRORS: 1
// A lower unit overflows (68 s), and a later unit is unknown: the error is the unknown unit, as
// no valid spelling of the literal exists to propose (it used to propose T#0ms).
#include <iecoop/iecoop.hpp>

using namespace iecoop;
int main() {
#ifdef IECOOP_COMPILE_FAIL
  constexpr TIME t = "T#5m68s1x"_iec;
#else
  constexpr TIME t = "T#6m8s1ms"_iec;
#endif
  return t.count() > 0 ? 0 : 1;
}
