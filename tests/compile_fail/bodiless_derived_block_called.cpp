// EXPECT: iecoop: the block has no body on any level
// EXPECT: bodiless_derived_block_called\.cpp:25:
// EXPECT-ERRORS: 1
// A block that extends a block without a body may leave out its own too; then no level has one,
// and the block is only extended, like its base — a call of it is refused as for any block
// without a body. Its twin states the (empty) implementation.
#include <iecoop/iecoop.hpp>
using namespace iecoop;
struct FB_Base : function_block<FB_Base> {
  INT iValue;
  virtual ~FB_Base() = default;
};
struct FB_Derived : extends<FB_Derived, FB_Base> {
  BOOL bFlag;
#ifndef IECOOP_COMPILE_FAIL
  void body() override {}  // an empty implementation
#endif
};
struct FB_Leaf : extends<FB_Leaf, FB_Derived> {
  void body() override { iValue = iValue + 1; }
};
int main() {
  FB_Derived fb;
#ifdef IECOOP_COMPILE_FAIL
  fb();
#else
  fb();
#endif
  FB_Leaf leaf;
  leaf();
  return leaf.iValue == 1 && fb.iValue == 0 ? 0 : 1;
}
