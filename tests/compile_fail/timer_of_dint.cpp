// EXPECT: iecoop: a timer measures TIME or LTIME
// The timers measure TIME (TON, TOF, TP) or LTIME (LTON, LTOF, LTP), nothing else.
#include <iecoop/iecoop.hpp>
using namespace iecoop;
#ifdef IECOOP_COMPILE_FAIL
using timer = on_delay_timer<DINT>;
#else
using timer = on_delay_timer<LTIME>;  // LTON
#endif
int main() {
  timer tmr;
  tmr();
  return tmr.Q ? 1 : 0;
}
