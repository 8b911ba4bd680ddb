// EXPECT: only explicitly
// EXPECT: spelled<'B', 'O', 'O', 'L'>
// EXPECT-ERRORS: 1
// `r *= (a > c)` is ST's `r := r * (a > c);`, which does not compile: a comparison is a BOOL,
// no number. (C++ would multiply by 0 or 1.)
#include <iecoop/iecoop.hpp>
using namespace iecoop;
int main() {
  REAL r = 1.5f;
  const INT a = 3;
  const INT c = 1;
#ifdef IECOOP_COMPILE_FAIL
  r *= (a > c);
#else
  if (a > c) r *= 2.0f;
#endif
  return r == 3.0f ? 0 : 1;
}
