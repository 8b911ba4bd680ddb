// EXPECT: iecoop: an ARRAY's initial value is out of range
// 300 does not fit the SINTs of `VAR CONSTANT a : ARRAY[1..2] OF SINT := [1, 300];`.
#include <iecoop/iecoop.hpp>
using namespace iecoop;
int main() {
#ifdef IECOOP_COMPILE_FAIL
  constexpr ARRAY<SINT, 1, 2> aLimits = array_init(1, 300);
  (void)aLimits;
#else
  constexpr ARRAY<SINT, 1, 2> aLimits = array_init(1, 100);
  (void)aLimits;
#endif
}
