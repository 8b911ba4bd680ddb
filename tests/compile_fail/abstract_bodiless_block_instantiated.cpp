// EXPECT: FB_Base
// EXPECT: abstract_bodiless_block_instantiated\.cpp:28:
// An ABSTRACT block without a body of its own is extended, not instantiated. Its twin
// instantiates the block extending it, whose body runs.
#include <iecoop/iecoop.hpp>
using namespace iecoop;
// FUNCTION_BLOCK ABSTRACT FB_Base  (no implementation)
struct FB_Base : function_block<FB_Base> {
  INT iRuns;
  virtual ~FB_Base() = default;

 protected:
  FB_Base() = default;
};
// FUNCTION_BLOCK FB_Derived EXTENDS FB_Base
//   iRuns := iRuns + 1; SUPER^();
struct FB_Derived : extends<FB_Derived, FB_Base> {
  void body() override {
    iRuns = iRuns + 1;
    SUPER::body();  // the base's implementation: empty
  }
};
int main() {
#ifndef IECOOP_COMPILE_FAIL
  FB_Derived fb;
  fb();
#else
  FB_Base fb;
#endif
  return fb.iRuns == 1 ? 0 : 1;
}
