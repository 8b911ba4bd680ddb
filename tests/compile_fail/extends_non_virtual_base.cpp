// EXPECT: must dispatch its body virtually
// An extended block must be polymorphic, as CODESYS dispatches a hierarchy's bodies virtually.
#include <iecoop/iecoop.hpp>
using namespace iecoop;
struct FB_Base : function_block<FB_Base> {
#ifdef IECOOP_COMPILE_FAIL
  void body() {}
#else
  virtual ~FB_Base() = default;
  virtual void body() {}
#endif
};
struct FB_Derived : extends<FB_Derived, FB_Base> {
  void body() override {}
};
int main() {
  FB_Derived fb;
  fb();
}
