// EXPECT: positional arguments come before named ones
// Positional arguments first; after a named one, all must be named.
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
  return fb.M({"a"_ = 1, 2}).value();
#else
  return fb.M({1, "b"_ = 2}).value();
#endif
}
