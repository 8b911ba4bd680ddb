// EXPECT: have no implicit common type
// EXPECT: spelled<'U', 'I', 'N', 'T'>
// EXPECT-ERRORS: 1
// INT and UINT have no common type under IEC's implicit conversions: convert one first.
#include <iecoop/iecoop.hpp>

using namespace iecoop;
int main() {
  const INT a = -1;
  const UINT b = 2;
#ifdef IECOOP_COMPILE_FAIL
  const auto sum = a + b;
#else
  const auto sum = a + UINT_TO_INT(b);
#endif
  return sum == 1 ? 0 : 1;
}
