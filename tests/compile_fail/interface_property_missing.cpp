// EXPECT: P_Result_Set
// A block that IMPLEMENTS an interface but lacks an accessor of one of its properties does
// not compile where it is instantiated, and the compiler names the missing accessor.
#include <iecoop/iecoop.hpp>
using namespace iecoop;
struct I_Math : interface_base<I_Math> {
  virtual REAL P_Result_Get() = 0;  // PROPERTY P_Result : REAL
  virtual void P_Result_Set(REAL value) = 0;
  [[no_unique_address]] property<REAL, &I_Math::P_Result_Get, &I_Math::P_Result_Set> P_Result{this};
};
struct FB_Math : function_block<FB_Math, implements<I_Math>> {
  REAL rResult;
  void body() {}
  REAL P_Result_Get() override { return rResult; }
#ifndef IECOOP_COMPILE_FAIL
  void P_Result_Set(REAL value) override { rResult = value; }
#endif
};
int main() {
  FB_Math fb;
  fb.rResult = 2.0f;
  itf<I_Math> ip = fb;
  return ip->P_Result == 2.0f ? 0 : 1;
}
