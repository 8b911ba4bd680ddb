// EXPECT: a VAR_OUTPUT is not passed in
// A method's output is read after the call with =>, never passed in.
#include <iecoop/iecoop.hpp>
using namespace iecoop;
struct M_vars {
  INT a;
  output<INT> r;
};
struct FB : function_block<FB> {
  void body() {}
  void M(args<M_vars> in) { in.r = in.a * 2; }
};
int main() {
  FB fb;
  INT result;
#ifdef IECOOP_COMPILE_FAIL
  fb.M({1, result});
#else
  fb.M({1, "r"_ >> result});
#endif
  return result == 2 ? 0 : 1;
}
