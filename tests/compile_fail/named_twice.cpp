// EXPECT: names the same variable twice
// A call may name each parameter once.
#include <iecoop/iecoop.hpp>
using namespace iecoop;
struct FB : function_block<FB> {
  INT x;
  using VAR_INPUT = pins<&FB::x>;
  void body() {}
};
int main() {
  FB fb;
#ifdef IECOOP_COMPILE_FAIL
  fb("x"_ = 1, "x"_ = 2);
#else
  fb("x"_ = 2);
#endif
  return fb.x == 2 ? 0 : 1;
}
