// Code-generation checks (see cmake/check_codegen.cmake), compiled with -O2 to assembly:
//   iecoop_same_<name>_a / _b      must compile to the same instructions;
//   iecoop_one_indirect_<name>     must contain exactly one indirect call or jump.
// They hold the zero-overhead promises: a property is its accessor call, a named call is
// the hand-written assignments and call, an interface call is one virtual call.
#include <iecoop/iecoop.hpp>

using namespace iecoop;

namespace {

struct FB_A : function_block<FB_A> {
  INT iA;
  INT iB;
  INT prop_iA_Get() { return iA; }
  void prop_iA_Set(INT value) { iB = value; }
  [[no_unique_address]] property<INT, &FB_A::prop_iA_Get, &FB_A::prop_iA_Set> prop_iA{this};
  void body() { iA = iA + 1; }
};

struct FB_Add : function_block<FB_Add> {
  INT a;
  INT b;
  INT sum;
  using VAR_INPUT = pins<&FB_Add::a, &FB_Add::b>;
  using VAR_OUTPUT = pins<&FB_Add::sum>;
  void body() { sum = a + b; }
};

}  // namespace

// With external linkage, so that the compiler cannot know every block implementing it (it
// would otherwise devirtualize the calls below).
struct I_Math : interface_base<I_Math> {
  virtual REAL M_Add(REAL value) = 0;
  virtual REAL P_Result_Get() = 0;
  [[no_unique_address]] property<REAL, &I_Math::P_Result_Get> P_Result{this};
};

extern "C" {

// A property read is its Get accessor.
short iecoop_same_property_get_a(FB_A& fb) { return INT(fb.prop_iA).value(); }
short iecoop_same_property_get_b(FB_A& fb) { return fb.prop_iA_Get().value(); }

// A property write is its Set accessor.
void iecoop_same_property_set_a(FB_A& fb, short v) { fb.prop_iA = INT(v); }
void iecoop_same_property_set_b(FB_A& fb, short v) { fb.prop_iA_Set(INT(v)); }

// A property in an expression is the accessor's value in it.
bool iecoop_same_property_compare_a(FB_A& fb) { return fb.prop_iA > 500; }
bool iecoop_same_property_compare_b(FB_A& fb) { return fb.prop_iA_Get() > 500; }

// A named call is the assignments, the body and the read of the output.
short iecoop_same_named_call_a(FB_Add& fb, short x) {
  INT result;
  fb("a"_ = INT(x), "b"_ = INT(2), "sum"_ >> result);
  return result.value();
}
short iecoop_same_named_call_b(FB_Add& fb, short x) {
  fb.a = INT(x);
  fb.b = INT(2);
  fb.body();
  return fb.sum.value();
}

// A method call through an interface variable: one virtual call (plus the check for 0).
float iecoop_one_indirect_interface_method(const itf<I_Math>& ip) { return ip->M_Add(3.0f); }
// An interface property read through it: the same.
float iecoop_one_indirect_interface_property(const itf<I_Math>& ip) { return REAL(ip->P_Result); }

}  // extern "C"
