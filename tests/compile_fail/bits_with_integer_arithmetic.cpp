// EXPECT: have no implicit common type
// EXPECT: spelled<'U', 'I', 'N', 'T'>
// EXPECT-ERRORS: 1
// A bit string and an integer (WORD and UINT) have no common type under IEC's implicit
// conversions: convert one first. (INT and UINT have one: both widen to DINT.)
#include <iecoop/iecoop.hpp>

using namespace iecoop;
int main() {
  const WORD a = 0xFFFF;
  const UINT b = 2;
#ifdef IECOOP_COMPILE_FAIL
  const auto sum = a + b;
#else
  const auto sum = WORD_TO_UINT(a) + b;
#endif
  return sum == 65537 ? 0 : 1;
}
