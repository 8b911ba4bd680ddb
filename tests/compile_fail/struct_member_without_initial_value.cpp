// EXPECT: iecoop: a member of the STRUCT `T` \(its name spelled in this report\) has a C\+\+ type
// EXPECT: 'e', 'M', 'o', 'd', 'e'
// EXPECT-ERRORS: 1
// EXPECT: struct_member_without_initial_value.cpp:21
// A STRUCT member of a C++ enum type without an initial value is undefined wherever the STRUCT
// is default-initialised (a local variable, a member of a block declared as a local). iecoop
// refuses the STRUCT where it sees it: a var<>, an ARRAY's element, a block's pin, a method's
// variables.
#include <iecoop/iecoop.hpp>
using namespace iecoop;
enum class E_Mode : INT::rep { Off, Manual, Auto };
struct ST_Axis {  // TYPE ST_Axis : STRUCT rPos : REAL; eMode : E_Mode; END_STRUCT END_TYPE
  REAL rPos;
#ifdef IECOOP_COMPILE_FAIL
  E_Mode eMode;
#else
  E_Mode eMode = E_Mode::Off;
#endif
};
int main() {
  ARRAY<ST_Axis, 1, 2> aAxes;
  return aAxes[2].eMode == E_Mode::Off ? 0 : 1;
}
