// EXPECT: iecoop: the block is declared no_explicit_call
// EXPECT: no_explicit_call_called\.cpp:28:
// EXPECT-ERRORS: 1
// {attribute 'no_explicit_call'}: the block's instance is not called, only its methods (CODESYS
// error C0554) — also through a reference to it. A block extending it is called as ever.
#include <iecoop/iecoop.hpp>
using namespace iecoop;
// {attribute 'no_explicit_call' := 'use the methods'}
// FUNCTION_BLOCK ABSTRACT FB_Axis  (no implementation)
struct FB_Axis : function_block<FB_Axis, attributes<no_explicit_call>> {
  LREAL fPosition;
  virtual ~FB_Axis() = default;
  virtual void MoveTo(LREAL fTarget) { fPosition = fTarget; }

 protected:
  FB_Axis() = default;
};
// FUNCTION_BLOCK FB_Linear EXTENDS FB_Axis
struct FB_Linear : extends<FB_Linear, FB_Axis> {
  INT iCycles;
  void body() override { iCycles = iCycles + 1; }
};
int main() {
  FB_Linear fbLinear;
  FB_Axis& axis = fbLinear;
  axis.MoveTo(2.5);
#ifdef IECOOP_COMPILE_FAIL
  axis();  // ST: refAxis();
#else
  fbLinear();
#endif
  return fbLinear.fPosition == 2.5 ? 0 : 1;
}
