// EXPECT: only explicitly
// EXPECT: spelled<'D', 'I', 'N', 'T'>
// EXPECT: spelled<'I', 'N', 'T'>
// EXPECT-ERRORS: 1
// Arguments follow IEC's implicit conversions: a DINT does not go into an INT input.
#include <iecoop/iecoop.hpp>
using namespace iecoop;
struct FB : function_block<FB> {
  INT iValue;
  using VAR_INPUT = pins<&FB::iValue>;
  void body() {}
};
int main() {
  FB fb;
  const DINT wide = 5;
#ifdef IECOOP_COMPILE_FAIL
  fb("iValue"_ = wide);
#else
  fb("iValue"_ = DINT_TO_INT(wide));
#endif
}
