// EXPECT: not a constant expression
// A run-time C++ int may not fit an INT: IEC needs an explicit conversion (DINT_TO_INT).
#include <iecoop/iecoop.hpp>

using namespace iecoop;
int main(int argc, char**) {
#ifdef IECOOP_COMPILE_FAIL
  const INT count = argc;
#else
  const INT count = DINT_TO_INT(argc);
#endif
  return count == 1 ? 0 : 1;
}
