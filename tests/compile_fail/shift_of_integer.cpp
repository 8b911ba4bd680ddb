// EXPECT: iecoop: SHL, SHR, ROL and ROR shift a bit string
// IEC's SHL shifts ANY_BIT: an INT is converted to a WORD first.
#include <iecoop/iecoop.hpp>
using namespace iecoop;
int main() {
  INT iFlags = 5;
#ifdef IECOOP_COMPILE_FAIL
  WORD wOut = SHL(iFlags, 2);
#else
  WORD wOut = SHL(INT_TO_WORD(iFlags), 2);
#endif
  (void)wOut;
}
