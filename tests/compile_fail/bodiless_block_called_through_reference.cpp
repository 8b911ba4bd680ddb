// EXPECT: iecoop: the block has no body on any level
// EXPECT: bodiless_block_called_through_reference\.cpp:29:
// EXPECT-ERRORS: 1
// A block without a body of its own is extended, never called: C++ has no body in it to dispatch
// a call through a reference to it to the derived block's. Its twin gives the base its empty
// body, virtual, so that the call through the reference runs FB_Derived's (as in ST).
#include <iecoop/iecoop.hpp>
using namespace iecoop;
// FUNCTION_BLOCK ABSTRACT FB_Base  (no implementation)
struct FB_Base : function_block<FB_Base> {
  INT iRuns;
  virtual ~FB_Base() = default;
#ifndef IECOOP_COMPILE_FAIL
  virtual void body() {}
#endif

 protected:
  FB_Base() = default;
};
// FUNCTION_BLOCK FB_Derived EXTENDS FB_Base
struct FB_Derived : extends<FB_Derived, FB_Base> {
  void body() override { iRuns = iRuns + 1; }
};
int main() {
  FB_Derived fbDerived;
  FB_Base& base = fbDerived;  // refBase : REFERENCE TO FB_Base := fbDerived;
  fbDerived();                // the derived block itself is called as ever
#ifdef IECOOP_COMPILE_FAIL
  base();  // refBase();
#else
  base();
#endif
  return fbDerived.iRuns == 2 ? 0 : 1;
}
