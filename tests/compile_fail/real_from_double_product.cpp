// EXPECT: only explicitly
// EXPECT: spelled<'L', 'R', 'E', 'A', 'L'>
// EXPECT-ERRORS: 1
// A C++ double constant is an LREAL, so `i * 2.5` is an LREAL, which goes into a REAL only
// explicitly. ST's `r := i * 2.5;` is written with a REAL constant: `i * 2.5f`.
#include <iecoop/iecoop.hpp>
using namespace iecoop;
int main() {
  REAL r;
  const INT i = 3;
#ifdef IECOOP_COMPILE_FAIL
  r = i * 2.5;
#else
  r = i * 2.5f;
#endif
  return r == 7.5f ? 0 : 1;
}
