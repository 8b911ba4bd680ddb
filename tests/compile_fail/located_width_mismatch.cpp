// EXPECT: iecoop: a bit address \(%IX, %QX, %MX\) holds a BOOL
// The variable's type must fit the size of its address: a bit holds a BOOL, a word
// (%IW) an INT, WORD or UINT.
#include <iecoop/io/located.hpp>
using namespace iecoop;
int main() {
#ifdef IECOOP_COMPILE_FAIL
  located<INT, "%IX0.5"> iValue;  // iValue AT %IX0.5 : INT;
#else
  located<INT, "%IW2"> iValue;  // iValue AT %IW2 : INT;
#endif
  return iValue > 0 ? 1 : 0;
}
