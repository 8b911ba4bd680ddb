// EXPECT: iecoop: MOD takes integers
// ST's MOD is defined for integers only.
#include <iecoop/iecoop.hpp>
using namespace iecoop;
int main() {
  REAL rAngle = 370.0f;
#ifdef IECOOP_COMPILE_FAIL
  auto rWrapped = MOD(rAngle, 360.0f);
#else
  auto rWrapped = MOD(REAL_TO_DINT(rAngle), 360);
#endif
  (void)rWrapped;
}
