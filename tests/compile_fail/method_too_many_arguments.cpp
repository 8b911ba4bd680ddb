// EXPECT: more arguments than the METHOD or FUNCTION has variables
// EXPECT-ERRORS: 1
// A positional call cannot pass more arguments than the method declares.
#include <iecoop/iecoop.hpp>
using namespace iecoop;
struct M_vars {
  INT a;
  INT b;
};
struct FB : function_block<FB> {
  void body() {}
  INT M(args<M_vars> in) { return in.a + in.b; }
};
int main() {
  FB fb;
#ifdef IECOOP_COMPILE_FAIL
  return fb.M({1, 2, 3}).value();
#else
  return fb.M({1, 2}).value();
#endif
}
