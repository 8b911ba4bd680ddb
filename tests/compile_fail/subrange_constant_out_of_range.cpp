// EXPECT: iecoop: constant outside the subrange
// CODESYS rejects `i := 5000;` for `i : INT(-4095..4095)` while compiling.
#include <iecoop/iecoop.hpp>
using namespace iecoop;
int main() {
  subrange<INT, -4095, 4095> i;
#ifdef IECOOP_COMPILE_FAIL
  i = 5000;
#else
  i = 4000;
#endif
}
