// EXPECT: iecoop: the components of this enumeration are not declared, so its names are not known
// {attribute 'to_string'} makes TO_STRING give the component's name: iecoop knows the names of
// the components listed in enum_components<E>.
#include <iecoop/iecoop.hpp>
using namespace iecoop;
enum class E_Mode : INT::rep { Off, Manual, Auto };
template <>
inline constexpr bool iecoop::enum_to_string<E_Mode> = true;
#ifndef IECOOP_COMPILE_FAIL
template <>
inline constexpr auto iecoop::enum_components<E_Mode> = components<E_Mode::Off, E_Mode::Manual, E_Mode::Auto>{};
#endif
int main() {
  const STRING<> s = TO_STRING(E_Mode::Auto);
  return s == "Auto" ? 0 : 1;
}
