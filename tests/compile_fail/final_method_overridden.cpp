// EXPECT: final
// A FINAL method cannot be overridden.
#include <iecoop/iecoop.hpp>
using namespace iecoop;
struct FB_Base : function_block<FB_Base> {
  virtual ~FB_Base() = default;
  virtual void body() {}
#ifdef IECOOP_COMPILE_FAIL
  virtual INT Count() final { return 1; }  // METHOD FINAL Count : INT
#else
  virtual INT Count() { return 1; }
#endif
};
struct FB_Derived : extends<FB_Derived, FB_Base> {
  void body() override {}
  INT Count() override { return 2; }
};
int main() {
  FB_Derived fb;
  return fb.Count() == 2 ? 0 : 1;
}
