// EXPECT: VAR_IN_OUT needs a variable
// A VAR_IN_OUT refers to a variable; a value cannot be passed (CODESYS: no literal).
#include <iecoop/iecoop.hpp>
using namespace iecoop;
struct FB : function_block<FB> {
  in_out<INT> iValue;
  using VAR_IN_OUT = pins<&FB::iValue>;
  void body() { iValue = iValue + 1; }
};
int main() {
  FB fb;
  INT variable = 1;
#ifdef IECOOP_COMPILE_FAIL
  fb("iValue"_ = INT(5));
#else
  fb("iValue"_ = variable);
#endif
  return variable == 2 ? 0 : 1;
}
