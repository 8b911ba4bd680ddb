// EXPECT: override
// A base with other virtual functions but a non-virtual body is rejected too: through a base
// reference its own body would run, not the derived one.
#include <iecoop/iecoop.hpp>
using namespace iecoop;
struct FB_Base : function_block<FB_Base> {
  virtual ~FB_Base() = default;
#ifdef IECOOP_COMPILE_FAIL
  void body() {}
#else
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
