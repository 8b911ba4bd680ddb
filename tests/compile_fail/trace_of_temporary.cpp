// EXPECT: iecoop: a trace records a variable, not a value
// A trace reads its channels after every cycle: a value computed once is gone by then.
#include <iecoop/iecoop.hpp>
using namespace iecoop;
int main() {
  INT iCount = 5;
  trace_recorder<1024> trace;
#ifdef IECOOP_COMPILE_FAIL
  trace.add("iCount + 1", iCount + 1);
#else
  trace.add("iCount", iCount);
#endif
}
