// EXPECT: a property is declared `\[\[no_unique_address\]\] property<T, &FB::Name_Get, &FB::Name_Set> Name\{this\}
// A property is declared with the initializer {this}, by which it checks, when its block is
// constructed, that it sits at the block's address.
#include <iecoop/iecoop.hpp>
using namespace iecoop;
struct FB_A : function_block<FB_A> {
  INT iA;
  INT prop_iA_Get() { return iA; }
  void prop_iA_Set(INT value) { iA = value; }
#ifdef IECOOP_COMPILE_FAIL
  [[no_unique_address]] property<INT, &FB_A::prop_iA_Get, &FB_A::prop_iA_Set> prop_iA;
#else
  [[no_unique_address]] property<INT, &FB_A::prop_iA_Get, &FB_A::prop_iA_Set> prop_iA{this};
#endif
  void body() { iA = iA + 1; }
};
int main() {
  FB_A fbA;
  fbA.prop_iA = 5;
  return fbA.prop_iA == 5 ? 0 : 1;
}
