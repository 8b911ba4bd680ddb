// EXPECT: iecoop: a trace triggers on a variable, not on a value
// The trigger is read after every cycle: an expression's value is gone by then; a condition is
// what trigger_when is for.
#include <iecoop/iecoop.hpp>
using namespace iecoop;
int main() {
  BOOL bJam;
  BOOL bStop;
  trace_recorder<1024> trace;
#ifdef IECOOP_COMPILE_FAIL
  trace.trigger_on(bJam & bStop, trace_edge::rising, 10);
#else
  trace.trigger_on(bJam, trace_edge::rising, 10);
  (void)bStop;
#endif
}
