// EXPECT: a FUNCTION_BLOCK needs its code as `void body\(\)`
// EXPECT-ERRORS: 1
// A block's code is its body() (ST: the implementation part).
#include <iecoop/iecoop.hpp>
using namespace iecoop;
struct FB : function_block<FB> {
  INT iValue;
#ifndef IECOOP_COMPILE_FAIL
  void body() { iValue = iValue + 1; }
#endif
};
int main() {
  FB fb;
  fb();
}
