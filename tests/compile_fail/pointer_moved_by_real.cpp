// EXPECT: iecoop: a pointer moves by an integer number of bytes
// CODESYS adds integers to pointers, never REALs.
#include <iecoop/iecoop.hpp>
using namespace iecoop;
int main() {
  ARRAY<DINT, 1, 4> aValues;
  POINTER_TO<DINT> p = ADR(aValues[1]);
#ifdef IECOOP_COMPILE_FAIL
  p = p + 4.0;
#else
  p = p + 4;
#endif
}
