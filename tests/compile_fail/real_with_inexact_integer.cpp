// EXPECT: only explicitly
// EXPECT: spelled<'D', 'I', 'N', 'T'>
// EXPECT: spelled<'R', 'E', 'A', 'L'>
// EXPECT-ERRORS: 1
// A REAL cannot hold every DINT exactly, so ST converts DINT to REAL only explicitly (CODESYS
// warns C0197): r * d needs DINT_TO_REAL(d); with LREAL it is exact and implicit.
#include <iecoop/iecoop.hpp>
using namespace iecoop;
int main() {
  REAL r = 1.5f;
  const DINT d = 2;
#ifdef IECOOP_COMPILE_FAIL
  r = r * d;
#else
  r = r * DINT_TO_REAL(d);
#endif
  return r == 3.0f ? 0 : 1;
}
