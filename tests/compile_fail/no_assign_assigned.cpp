// EXPECT: iecoop: the block is declared no_assign
// EXPECT: no_assign_assigned\.cpp:24:
// EXPECT-ERRORS: 1
// {attribute 'no_assign'}: one instance of the block is not assigned to another (ST fbA := fbB),
// typically because it holds a pointer that must not be copied. Its twin copies the one
// variable meant to be copied.
#include <iecoop/iecoop.hpp>
using namespace iecoop;
// {attribute 'no_assign'}
// FUNCTION_BLOCK FB_Buffer
struct FB_Buffer : function_block<FB_Buffer, attributes<no_assign>> {
  POINTER_TO<INT> pData;
  INT iCount;
  using VAR_INPUT = pins<&FB_Buffer::pData>;
  void body() { iCount = iCount + 1; }
};
int main() {
  INT a = 1;
  FB_Buffer fbA;
  FB_Buffer fbB;
  fbA("pData"_ = ADR(a));
  fbB();
#ifdef IECOOP_COMPILE_FAIL
  fbB = fbA;  // ST: fbB := fbA;
#else
  fbB.iCount = fbA.iCount;
#endif
  return fbB.iCount == 1 && fbB.pData == 0 ? 0 : 1;
}
