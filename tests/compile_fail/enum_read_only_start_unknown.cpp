// EXPECT: iecoop: a variable of an enumeration starts at its first component in ST
// EXPECT: E_Mode
// EXPECT: enum_read_only_start_unknown.cpp:15
// EXPECT-ERRORS: 1
// ST starts a VAR_OUTPUT of an enumeration declared without an initial value at its first
// component: iecoop knows the first component from the declared components (or the type's
// initial value), and refuses a read_only<E, FB> (an output only its block writes) it cannot start.
#include <iecoop/iecoop.hpp>
using namespace iecoop;
enum class E_Mode : INT::rep { Off = 3, Manual, Auto };
#ifndef IECOOP_COMPILE_FAIL
template <>
inline constexpr auto iecoop::enum_components<E_Mode> = components<E_Mode::Off, E_Mode::Manual, E_Mode::Auto>{};
#endif
struct FB_Mode : function_block<FB_Mode> {
  // VAR_OUTPUT eMode : E_Mode; END_VAR  (starts at Off, 3; only FB_Mode writes it)
  read_only<E_Mode, FB_Mode> eMode;
  void body() {}
};
int main() {
  FB_Mode fb;
  fb();
  return fb.eMode == E_Mode::Off ? 0 : 1;
}
