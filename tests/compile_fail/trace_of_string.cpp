// EXPECT: iecoop: a trace records BOOL, integers, bit strings, REAL, LREAL, TIME, LTIME, dates and enumerations
// A sample holds scalars; a STRING is recorded character by character if at all.
#include <iecoop/iecoop.hpp>
using namespace iecoop;
int main() {
  STRING<20> sRecipe = "water";
  INT iLength = 0;
  trace_recorder<1024> trace;
#ifdef IECOOP_COMPILE_FAIL
  trace.add("sRecipe", sRecipe);
#else
  iLength = LEN(sRecipe);
  trace.add("iLength", iLength);
#endif
}
