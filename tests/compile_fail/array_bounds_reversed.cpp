// EXPECT: iecoop: an ARRAY's lower bound must not exceed its upper bound
// ST's ARRAY[10..1] does not compile in CODESYS either.
#include <iecoop/iecoop.hpp>
using namespace iecoop;
int main() {
#ifdef IECOOP_COMPILE_FAIL
  ARRAY<INT, 10, 1> aValues;
  (void)aValues;
#else
  ARRAY<INT, 1, 10> aValues;
  (void)aValues;
#endif
}
