// EXPECT: iecoop: components<...> lists a value that is no component of the enumeration
// components<...> lists enumerators; a number cast to the enumeration has no name.
#include <iecoop/iecoop.hpp>
using namespace iecoop;
enum E_State : INT::rep { Idle, Run = 10, Fault };
#ifdef IECOOP_COMPILE_FAIL
template <>
inline constexpr auto iecoop::enum_components<E_State> = components<Idle, Run, E_State(12)>{};
#else
template <>
inline constexpr auto iecoop::enum_components<E_State> = components<Idle, Run, Fault>{};
#endif
int main() { return is_component(Fault) ? 0 : 1; }
