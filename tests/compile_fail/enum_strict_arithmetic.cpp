// EXPECT: iecoop: \{attribute 'strict'\} forbids arithmetic with an enumeration
// {attribute 'strict'} TYPE E_Step : (Idle, Fill, Heat); END_TYPE -- eStep + 1 does not compile.
#include <iecoop/iecoop.hpp>
using namespace iecoop;
enum E_Step : INT::rep { Idle, Fill, Heat };
template <>
inline constexpr bool iecoop::enum_strict<E_Step> = true;
int main() {
  const E_Step eStep = Fill;
#ifdef IECOOP_COMPILE_FAIL
  const INT iNext = eStep + 1;
#else
  const INT iNext = TO_INT(eStep) + 1;
#endif
  return iNext == 2 ? 0 : 1;
}
