// EXPECT: a property's options are owner_only_get, owner_only_set, monitoring::call and
// A misspelt option of a property would otherwise be ignored silently (its monitoring mode
// would quietly be 'call').
#include <iecoop/iecoop.hpp>
using namespace iecoop;
struct FB_A : function_block<FB_A> {
  INT iA;
  INT iA_monitor;
  INT prop_iA_Get() { return iA; }
  void prop_iA_Set(INT value) { iA = value; }
#ifdef IECOOP_COMPILE_FAIL
  [[no_unique_address]] property<INT, &FB_A::prop_iA_Get, &FB_A::prop_iA_Set, int> prop_iA{this};
#else
  [[no_unique_address]] property<INT, &FB_A::prop_iA_Get, &FB_A::prop_iA_Set, monitoring::variable<&FB_A::iA_monitor>>
      prop_iA{this};
#endif
  void body() {}
};
int main() {
  FB_A fbA;
  fbA.prop_iA = 5;
  return fbA.prop_iA == 5 ? 0 : 1;
}
