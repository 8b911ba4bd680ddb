// EXPECT: a METHOD's or FUNCTION's VAR \(temp<T>\) is its own, not passed by the caller
// A METHOD's VAR (temp<T> among its variables) is not a parameter: a call cannot pass it.
#include <iecoop/iecoop.hpp>
using namespace iecoop;
struct Swap_vars {
  INT iNew;
  temp<INT> iOld;  // VAR iOld : INT; END_VAR
};
struct FB : function_block<FB> {
  INT iValue;
  INT Swap(args<Swap_vars> in) {
    in.iOld = iValue;
    iValue = in.iNew;
    return in.iOld;
  }
  void body() {}
};
int main() {
  FB fb;
#ifdef IECOOP_COMPILE_FAIL
  return fb.Swap({"iNew"_ = 1, "iOld"_ = 2}).value();
#else
  return fb.Swap({"iNew"_ = 1}).value();
#endif
}
