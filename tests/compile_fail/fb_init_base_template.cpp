// EXPECT: iecoop: a block that others EXTENDS declares FB_Init as a template or with overloads
// EXPECT: fb_init_base_template.cpp:26
// CODESYS has one FB_Init per block, and runs each level's on the whole derived block; iecoop
// calls each level's own FB_Init, which it can name only if there is one (not a template).
#include <iecoop/iecoop.hpp>
using namespace iecoop;
struct FB_Base : function_block<FB_Base> {
  FB_Base() { run_fb_init(*this); }
  virtual ~FB_Base() = default;
  INT iStarted = 0;
#ifdef IECOOP_COMPILE_FAIL
  template <class... A>
  BOOL FB_Init(BOOL, BOOL, A&&...) {
    iStarted = 1;
    return TRUE;
  }
#else
  BOOL FB_Init(BOOL, BOOL) {
    iStarted = 1;
    return TRUE;
  }
#endif
  virtual void body() {}
};
struct FB_Derived : extends<FB_Derived, FB_Base> {
  FB_Derived() { run_fb_init(*this); }
  BOOL FB_Init(BOOL, BOOL) {
    iStarted = iStarted + 1;
    return TRUE;
  }
  void body() override {}
};
int main() {
  FB_Derived fb;
  fb();
  return fb.iStarted == 2 ? 0 : 1;
}
