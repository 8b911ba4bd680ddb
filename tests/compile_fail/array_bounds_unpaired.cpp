// EXPECT: iecoop: ARRAY bounds come in pairs
// ST's ARRAY[1..10] has a lower and an upper bound per dimension.
#include <iecoop/iecoop.hpp>
using namespace iecoop;
int main() {
#ifdef IECOOP_COMPILE_FAIL
  ARRAY<INT, 10> aValues;
  (void)aValues;
#else
  ARRAY<INT, 1, 10> aValues;
  (void)aValues;
#endif
}
