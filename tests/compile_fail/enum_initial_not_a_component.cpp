// EXPECT: iecoop: enum_initial<E> is one of E's components
// EXPECT: enum_initial_not_a_component.cpp:15
// EXPECT-ERRORS: 1
// ST's `TYPE E_Valve : (Open, Closed) := Closed; END_TYPE` is enum_initial<E_Valve>, declared as
// one of E_Valve's components: a number, or another enumeration's component, is none.
#include <iecoop/iecoop.hpp>
using namespace iecoop;
enum class E_Valve : INT::rep { Open, Closed };
template <>
#ifdef IECOOP_COMPILE_FAIL
inline constexpr int iecoop::enum_initial<E_Valve> = 1;
#else
inline constexpr E_Valve iecoop::enum_initial<E_Valve> = E_Valve::Closed;
#endif
struct FB_Valve : function_block<FB_Valve> {
  var<E_Valve> eValve;  // eValve : E_Valve;  (starts at Closed)
  void body() {}
};
int main() {
  FB_Valve fb;
  fb();
  return fb.eValve == E_Valve::Closed ? 0 : 1;
}
