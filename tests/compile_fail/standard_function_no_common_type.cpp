// EXPECT: iecoop: the inputs of this generic standard function have types
// EXPECT: spelled<'W', 'O', 'R', 'D'>
// A WORD and an INT meet in no type in ST (a bit string and an integer): MAX of them does not
// compile, and the diagnostic spells both; convert one input, as ST requires.
#include <iecoop/iecoop.hpp>
using namespace iecoop;
int main() {
  WORD wRaw = 5;
  INT iLimit = 3;
#ifdef IECOOP_COMPILE_FAIL
  INT iMax = MAX(wRaw, iLimit);
#else
  INT iMax = MAX(WORD_TO_INT(wRaw), iLimit);
#endif
  (void)iMax;
}
