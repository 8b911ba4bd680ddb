// EXPECT: iecoop: index an ARRAY with one index per dimension
// ST's aGrid[1] of an ARRAY[1..2, 1..3] is missing an index.
#include <iecoop/iecoop.hpp>
using namespace iecoop;
int main() {
  ARRAY<INT, 1, 2, 1, 3> aGrid;
#ifdef IECOOP_COMPILE_FAIL
  aGrid(1) = 5;
#else
  aGrid(1, 1) = 5;
#endif
}
