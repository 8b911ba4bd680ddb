// EXPECT: iecoop: a subrange's base type is an IEC integer
// CODESYS has subranges of integer types only.
#include <iecoop/iecoop.hpp>
using namespace iecoop;
int main() {
#ifdef IECOOP_COMPILE_FAIL
  subrange<REAL, 0, 100> r;
  (void)r;
#else
  subrange<INT, 0, 100> r;
  (void)r;
#endif
}
