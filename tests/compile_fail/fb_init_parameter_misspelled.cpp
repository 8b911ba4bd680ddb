// EXPECT: iecoop: the declaration names a variable
// EXPECT: 'f', 'M', 'i', 'n', 'i', 'm', 'u', 'n'
// EXPECT: fb_init_parameter_misspelled.cpp:30
// FB_Init parameters by name: a name that is no parameter of FB_Init (and no input) is refused.
#include <iecoop/iecoop.hpp>
using namespace iecoop;
struct FB_Clamp_Init {
  LREAL fMinimum = 0.0;
  LREAL fMaximum = 0.0;
};
struct FB_Clamp : function_block<FB_Clamp> {
  template <NamedInput... A>
  explicit FB_Clamp(A&&... a) {
    run_fb_init(*this, std::forward<A>(a)...);
  }
  LREAL fLow = 0.0;
  LREAL fHigh = 0.0;
  BOOL FB_Init(BOOL, BOOL, args<FB_Clamp_Init> in) {
    fLow = in.fMinimum;
    fHigh = in.fMaximum;
    return TRUE;
  }
  void body() {}
};
int main() {
#ifndef IECOOP_COMPILE_FAIL
  FB_Clamp fbClamp{"fMinimum"_ = 0.0, "fMaximum"_ = 100.0};  // fbClamp : FB_Clamp(fMinimum := 0.0, fMaximum := 100.0);
#else
  // fbClamp : FB_Clamp(fMinimun := 0.0, fMaximum := 100.0);  (C0000: no such parameter)
  FB_Clamp fbClamp{"fMinimun"_ = 0.0, "fMaximum"_ = 100.0};
#endif
  fbClamp();
  return fbClamp.fHigh > fbClamp.fLow ? 0 : 1;
}
