// EXPECT: iecoop: the VAR_INPUT or VAR_OUTPUT of the block `B` whose name this report spells has a C\+\+ type
// EXPECT: 'e', 'S', 't', 'a', 't', 'e'
// EXPECT-ERRORS: 1
// EXPECT: enum_pin_without_initial_value.cpp:24
// A VAR_INPUT of an enumeration is a plain C++ enum member: without an initial value C++
// leaves it undefined where the block is default-initialised (a local, a member), where ST
// starts it at its first component. iecoop refuses such a pin when the block is called.
#include <iecoop/iecoop.hpp>
using namespace iecoop;
enum class E_State : INT::rep { Idle = 1, Run };
struct FB_Drive : function_block<FB_Drive> {
#ifdef IECOOP_COMPILE_FAIL
  E_State eState;  // VAR_INPUT eState : E_State; END_VAR
#else
  E_State eState = E_State::Idle;
#endif
  BOOL bRun;
  using VAR_INPUT = pins<&FB_Drive::eState>;
  using VAR_OUTPUT = pins<&FB_Drive::bRun>;
  void body() { bRun = BOOL(eState == E_State::Run); }
};
int main() {
  FB_Drive fb;
  fb();
  return fb.bRun ? 1 : 0;
}
