// EXPECT: protected
// METHOD PROTECTED is callable inside its block and blocks derived from it, not outside.
#include <iecoop/iecoop.hpp>
using namespace iecoop;
struct FB_Base : function_block<FB_Base> {
  virtual ~FB_Base() = default;
  virtual void body() {}

 protected:
  void Helper() {}
};
struct FB_Derived : extends<FB_Derived, FB_Base> {
  void body() override { Helper(); }  // the derived block may call it
};
int main() {
  FB_Derived fb;
#ifdef IECOOP_COMPILE_FAIL
  fb.Helper();
#else
  fb();
#endif
}
