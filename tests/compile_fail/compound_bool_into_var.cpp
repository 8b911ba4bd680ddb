// EXPECT: BOOL is not a number
// EXPECT-ERRORS: 1
// `nCount += bPulse` is ST's `nCount := nCount + bPulse;`, which does not compile: a BOOL is
// no number. The same on a block's VAR as on a plain variable, in one error.
#include <iecoop/iecoop.hpp>
using namespace iecoop;
struct FB_Counter : function_block<FB_Counter> {
  BOOL bPulse;
  using VAR_INPUT = pins<&FB_Counter::bPulse>;
  var<INT> nCount;
  void body() {
#ifdef IECOOP_COMPILE_FAIL
    nCount += bPulse;
#else
    nCount += BOOL_TO_INT(bPulse);
#endif
  }
};
int main() {
  FB_Counter fb;
  fb("bPulse"_ = TRUE);
  return fb.nCount == 1 ? 0 : 1;
}
