// EXPECT: has no variable of the name spelled in
// EXPECT-ERRORS: 1
// EXPECT: spelled<'c'>
// A named argument of a method must name one of its variables.
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
  return fb.M({"c"_ = 1}).value();
#else
  return fb.M({"b"_ = 1}).value();
#endif
}
