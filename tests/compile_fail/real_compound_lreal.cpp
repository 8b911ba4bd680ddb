// EXPECT: only explicitly
// EXPECT: spelled<'L', 'R', 'E', 'A', 'L'>
// EXPECT: spelled<'R', 'E', 'A', 'L'>
// EXPECT-ERRORS: 1
// `r += l` is ST's `r := r + l;`: an LREAL result does not go into a REAL implicitly. (C++
// would narrow the double silently.)
#include <iecoop/iecoop.hpp>
using namespace iecoop;
int main() {
  REAL r = 1.5f;
  const LREAL l = 2.0;
#ifdef IECOOP_COMPILE_FAIL
  r += l;
#else
  r += LREAL_TO_REAL(l);
#endif
  return r == 3.5f ? 0 : 1;
}
