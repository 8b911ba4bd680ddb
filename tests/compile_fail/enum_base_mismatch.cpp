// EXPECT: iecoop: enum_base<E>::type must be the IEC integer type over the enumeration's C\+\+ base type
// TYPE E_Flags : (A := 1, B := 2) BYTE; END_TYPE is `enum E_Flags : BYTE::rep` with enum_base BYTE.
#include <iecoop/iecoop.hpp>
using namespace iecoop;
enum E_Flags : INT::rep { A = 1, B = 2 };
template <>
struct iecoop::enum_base<E_Flags> {
#ifdef IECOOP_COMPILE_FAIL
  using type = BYTE;
#else
  using type = INT;
#endif
};
int main() {
  const INT i = B;
  return i == 2 ? 0 : 1;
}
