// EXPECT: iecoop: more initial values than the ARRAY has elements
// ST's `ARRAY[1..3] OF INT := [1, 3(2)]` has four values for three elements.
#include <iecoop/iecoop.hpp>
using namespace iecoop;
int main() {
#ifdef IECOOP_COMPILE_FAIL
  ARRAY<INT, 1, 3> aValues = array_init(1, repeat<3>(2));
  (void)aValues;
#else
  ARRAY<INT, 1, 4> aValues = array_init(1, repeat<3>(2));
  (void)aValues;
#endif
}
