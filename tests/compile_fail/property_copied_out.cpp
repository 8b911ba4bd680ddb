// EXPECT: private
// `auto x = fb.prop;` would copy the property away from its block; it does not compile.
// Name the type (`INT x = fb.prop;`) or take the value (`auto x = fb.prop.get();`).
#include <iecoop/iecoop.hpp>
using namespace iecoop;
struct FB_A : function_block<FB_A> {
  INT iA;
  INT prop_iA_Get() const { return iA; }
  [[no_unique_address]] property<INT, &FB_A::prop_iA_Get> prop_iA{this};
  void body() { iA = iA + 1; }
};
int main() {
  FB_A fbA;
  fbA();
#ifdef IECOOP_COMPILE_FAIL
  auto value = fbA.prop_iA;
#else
  auto value = fbA.prop_iA.get();
#endif
  return value == 1 ? 0 : 1;
}
