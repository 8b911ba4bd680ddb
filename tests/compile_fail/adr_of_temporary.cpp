// EXPECT: iecoop: ADR takes a variable
// ST's ADR takes a variable; a function's result has no address.
#include <iecoop/iecoop.hpp>
using namespace iecoop;
int main() {
  INT iValue = 5;
#ifdef IECOOP_COMPILE_FAIL
  POINTER_TO<INT> p = ADR(iValue + 1);
  (void)p;
#else
  POINTER_TO<INT> p = ADR(iValue);
  (void)p;
#endif
}
