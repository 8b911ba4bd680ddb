// EXPECT: no VAR_OUTPUT of the name spelled in
// EXPECT-ERRORS: 1
// Only outputs can be read with => (IN is an input).
#include <iecoop/iecoop.hpp>
using namespace iecoop;
struct FB : function_block<FB> {
  BOOL IN;
  BOOL Q;
  using VAR_INPUT = pins<&FB::IN>;
  using VAR_OUTPUT = pins<&FB::Q>;
  void body() { Q = IN; }
};
int main() {
  FB fb;
  BOOL x;
#ifdef IECOOP_COMPILE_FAIL
  fb("IN"_ >> x);
#else
  fb("Q"_ >> x);
#endif
  return x ? 1 : 0;
}
