// EXPECT: iecoop: a multi-dimensional ARRAY is indexed a
// C++20 has no a[i, j]; a multi-dimensional ARRAY is indexed a(i, j).
#include <iecoop/iecoop.hpp>
using namespace iecoop;
int main() {
  ARRAY<INT, 1, 2, 1, 3> aGrid;
#ifdef IECOOP_COMPILE_FAIL
  aGrid[1] = 5;
#else
  aGrid(1, 3) = 5;
#endif
}
