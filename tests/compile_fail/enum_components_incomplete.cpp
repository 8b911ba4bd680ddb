// EXPECT: iecoop: components<...> misses a component of the enumeration
// EXPECT: spelled<'F', 'a', 'u', 'l', 't'>
// A component added to the enumeration (Fault, after Run) and forgotten in its list.
#include <iecoop/iecoop.hpp>
using namespace iecoop;
enum E_State : INT::rep { Idle, Run = 10, Fault };
#ifdef IECOOP_COMPILE_FAIL
template <>
inline constexpr auto iecoop::enum_components<E_State> = components<Idle, Run>{};
#else
template <>
inline constexpr auto iecoop::enum_components<E_State> = components<Idle, Run, Fault>{};
#endif
int main() { return is_component(Run) ? 0 : 1; }
