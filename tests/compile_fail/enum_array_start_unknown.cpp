// EXPECT: iecoop: a variable of an enumeration starts at its first component in ST
// EXPECT: E_Valve
// EXPECT: enum_array_start_unknown.cpp:1[0-9]
// EXPECT-ERRORS: 1
// The elements of an ARRAY OF an enumeration start at its first component (or at the type's
// initial value, `TYPE E_Valve : (...) := Closed;`): iecoop needs one of the two declared.
#include <iecoop/iecoop.hpp>
using namespace iecoop;
enum class E_Valve : INT::rep { Open, Closed };
#ifndef IECOOP_COMPILE_FAIL
template <>
inline constexpr E_Valve iecoop::enum_initial<E_Valve> = E_Valve::Closed;
#endif
int main() {
  ARRAY<E_Valve, 1, 4> aValves;  // aValves : ARRAY[1..4] OF E_Valve;
  return aValves[4] == E_Valve::Closed ? 0 : 1;
}
