// EXPECT: iecoop: the property has no Get accessor \(it is write-only\)
// A property without a Get accessor is write-only: reading it does not compile.
#include <iecoop/iecoop.hpp>
using namespace iecoop;
struct FB_Valve : function_block<FB_Valve> {
  REAL rOpening;
  void Opening_Set(REAL value) { rOpening = value; }
#ifndef IECOOP_COMPILE_FAIL
  REAL Opening_Get() const { return rOpening; }
  [[no_unique_address]] property<REAL, &FB_Valve::Opening_Get, &FB_Valve::Opening_Set> Opening{this};
#else
  [[no_unique_address]] property<REAL, nullptr, &FB_Valve::Opening_Set> Opening{this};  // Set only
#endif
  void body() {}
};
int main() {
  FB_Valve valve;
  valve.Opening = 0.5f;
  const REAL r = valve.Opening;  // r := valve.Opening;
  return r > 0.0f ? 0 : 1;
}
