// EXPECT: M_Mul
// A block that IMPLEMENTS an interface but lacks one of its methods does not compile where
// it is instantiated, and the compiler names the missing method.
#include <iecoop/iecoop.hpp>
using namespace iecoop;
struct I_Math : interface_base<I_Math> {
  struct vars {
    REAL rVal;
  };
  virtual REAL M_Add(args<vars> in) = 0;
  virtual REAL M_Mul(args<vars> in) = 0;
};
struct FB_Math : function_block<FB_Math, implements<I_Math>> {
  REAL rResult;
  void body() {}
  REAL M_Add(args<vars> in) override { return rResult = rResult + in.rVal; }
#ifndef IECOOP_COMPILE_FAIL
  REAL M_Mul(args<vars> in) override { return rResult = rResult * in.rVal; }
#endif
};
int main() {
  FB_Math fb;
  itf<I_Math> ip = fb;
  return ip->M_Add(2.0f) == 2.0f ? 0 : 1;
}
