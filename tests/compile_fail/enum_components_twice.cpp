// EXPECT: iecoop: components<...> lists a component twice
// Each component is listed once.
#include <iecoop/iecoop.hpp>
using namespace iecoop;
enum E_State : INT::rep { Idle, Run = 10, Fault };
#ifdef IECOOP_COMPILE_FAIL
template <>
inline constexpr auto iecoop::enum_components<E_State> = components<Idle, Run, Run, Fault>{};
#else
template <>
inline constexpr auto iecoop::enum_components<E_State> = components<Idle, Run, Fault>{};
#endif
int main() { return is_component(Fault) ? 0 : 1; }
