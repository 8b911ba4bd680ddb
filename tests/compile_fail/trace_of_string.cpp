// EXPECT: iecoop: a trace records BOOL, integers, bit strings, REAL, LREAL, TIME, LTIME, dates and enumerations
// A sample holds scalars; a STRING is recorded through a number taken from it, say its length.
#include <iecoop/iecoop.hpp>
using namespace iecoop;
int main() {
  STRING<20> sRecipe = "water";
  trace_recorder<1024> trace;
#ifdef IECOOP_COMPILE_FAIL
  trace.add("sRecipe", sRecipe);
#else
  INT iLength = LEN(sRecipe);
  trace.add("iLength", iLength);
#endif
}
