// EXPECT: only explicitly
// EXPECT: spelled<'D', 'I', 'N', 'T'>
// EXPECT-ERRORS: 1
// A DINT sum is a DINT: assigning it to an INT needs the conversion, as in ST.
#include <iecoop/iecoop.hpp>
using namespace iecoop;
int main() {
  const DINT d = 5;
  INT i;
#ifdef IECOOP_COMPILE_FAIL
  i = d + 1;
#else
  i = DINT_TO_INT(d + 1);
#endif
  return i == 6 ? 0 : 1;
}
