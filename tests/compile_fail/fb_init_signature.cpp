// EXPECT: has no FB_Init
// run_fb_init passes the declaration's parameters to FB_Init(bInitRetains, bInCopyCode, ...).
#include <iecoop/iecoop.hpp>
using namespace iecoop;
struct FB : function_block<FB> {
  explicit FB(INT id) { run_fb_init(*this, id); }
  INT iId;
  void body() {}
#ifdef IECOOP_COMPILE_FAIL
  BOOL FB_Init(BOOL bInitRetains, BOOL bInCopyCode) {
    (void)bInitRetains;
    (void)bInCopyCode;
    return TRUE;
  }
#else
  BOOL FB_Init(BOOL, BOOL, INT id) {
    iId = id;
    return TRUE;
  }
#endif
};
int main() {
  FB fb{INT(3)};
  fb();
}
