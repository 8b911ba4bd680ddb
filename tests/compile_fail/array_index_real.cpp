// EXPECT: iecoop: an ARRAY index is an integer
// An ARRAY index is ANY_INT (CODESYS rejects a REAL index).
#include <iecoop/iecoop.hpp>
using namespace iecoop;
int main() {
  ARRAY<INT, 1, 10> aValues;
  REAL rPos = 2.0f;
#ifdef IECOOP_COMPILE_FAIL
  aValues[rPos] = 1;
#else
  aValues[REAL_TO_DINT(rPos)] = 1;
#endif
}
