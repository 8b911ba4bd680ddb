// EXPECT: iecoop: a counter counts an IEC integer type
// The typed counters are made from one template; it takes IEC integer types only.
#include <iecoop/iecoop.hpp>
using namespace iecoop;
#ifdef IECOOP_COMPILE_FAIL
using CTU_REAL = up_counter<REAL, iec::dialect>;
#else
using CTU_REAL = up_counter<DINT, iec::dialect>;  // a counter of DINT is fine (CTU_DINT)
#endif
int main() {
  CTU_REAL counter;
  counter();
  return counter.Q ? 0 : 1;
}
