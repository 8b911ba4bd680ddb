// EXPECT: iecoop: LOWER_BOUND/UPPER_BOUND's dimension counts from 1
// A one-dimensional ARRAY has no dimension 2.
#include <iecoop/iecoop.hpp>
using namespace iecoop;
int main() {
  ARRAY<INT, 1, 10> aValues;
#ifdef IECOOP_COMPILE_FAIL
  DINT nLast = UPPER_BOUND(aValues, 2);
  (void)nLast;
#else
  DINT nLast = UPPER_BOUND(aValues, 1);
  (void)nLast;
#endif
}
