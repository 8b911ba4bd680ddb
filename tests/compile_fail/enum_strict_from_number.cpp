// EXPECT: iecoop: \{attribute 'strict'\} forbids making an enumeration of a number
// {attribute 'strict'} TYPE E_Step : (Idle, Fill, Heat); END_TYPE -- eStep := iStep; does not compile.
#include <iecoop/iecoop.hpp>
using namespace iecoop;
enum class E_Step : INT::rep { Idle, Fill, Heat };
template <>
inline constexpr bool iecoop::enum_strict<E_Step> = true;
int main() {
  E_Step eStep = E_Step::Idle;
  const INT iStep = 1;
#ifdef IECOOP_COMPILE_FAIL
  eStep = to_enum<E_Step>(iStep);
#else
  if (iStep == 1) eStep = E_Step::Fill;
#endif
  return eStep == E_Step::Fill ? 0 : 1;
}
