// EXPECT: iecoop: the inputs of this generic standard function have types
// EXPECT: spelled<'D', 'I', 'N', 'T'>
// A REAL cannot hold every DINT, so ST converts a DINT to REAL only explicitly: LIMIT of a
// DINT and REALs does not compile; DINT_TO_REAL (or LREAL bounds) does.
#include <iecoop/iecoop.hpp>
using namespace iecoop;
int main() {
  DINT diRaw = 1234;
  REAL rLow = 0.0f, rHigh = 100.0f;
#ifdef IECOOP_COMPILE_FAIL
  REAL rOut = LIMIT(rLow, diRaw, rHigh);
#else
  REAL rOut = LIMIT(rLow, DINT_TO_REAL(diRaw), rHigh);
#endif
  (void)rOut;
}
