// EXPECT: final
// A FINAL property (its accessors declared final) cannot be overridden in a derived block.
#include <iecoop/iecoop.hpp>
using namespace iecoop;
struct FB_Base : function_block<FB_Base> {
  virtual ~FB_Base() = default;
  virtual void body() {}
  INT iValue;
  virtual INT Value_Get() final { return iValue; }  // PROPERTY FINAL Value : INT
  [[no_unique_address]] property<INT, &FB_Base::Value_Get> Value{this};
};
struct FB_Derived : extends<FB_Derived, FB_Base> {
#ifdef IECOOP_COMPILE_FAIL
  INT Value_Get() override { return 1; }
#endif
  void body() override {}
};
int main() {
  FB_Derived derived;
  return derived.Value == 0 ? 0 : 1;
}
