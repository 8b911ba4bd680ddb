// EXPECT: iecoop: a variable of an enumeration starts at its first component in ST
// EXPECT: E_Mode
// EXPECT: enum_output_start_unknown.cpp:(16|22)
// EXPECT-ERRORS: 1
// ST starts a METHOD's VAR_OUTPUT of an enumeration declared without an initial value at its first
// component at every call: iecoop knows the first component from the declared components (or
// the type's initial value), and refuses an output<E> it cannot start.
#include <iecoop/iecoop.hpp>
using namespace iecoop;
enum class E_Mode : INT::rep { Off = 3, Manual, Auto };
#ifndef IECOOP_COMPILE_FAIL
template <>
inline constexpr auto iecoop::enum_components<E_Mode> = components<E_Mode::Off, E_Mode::Manual, E_Mode::Auto>{};
#endif
// METHOD Next : INT  VAR_INPUT n : INT; END_VAR  VAR_OUTPUT eMode : E_Mode; END_VAR
struct Next_vars {
  INT n;
  // VAR_OUTPUT eMode : E_Mode; END_VAR  (starts at Off, 3, at every call)
  output<E_Mode> eMode;
};
struct FB_Mode : function_block<FB_Mode> {
  INT Next(args<Next_vars> in) { return in.eMode.get() == E_Mode::Off ? in.n : INT(-1); }
  void body() {}
};
int main() {
  FB_Mode fb;
  return fb.Next({"n"_ = 0}) == 0 ? 0 : 1;
}
