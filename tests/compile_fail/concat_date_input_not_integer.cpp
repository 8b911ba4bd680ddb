// EXPECT: the inputs of CONCAT_DATE, CONCAT_TOD and CONCAT_DT are integers \(ANY_INT\)
// IEC's CONCAT_DATE takes ANY_INT components; a bit string is none.
#include <iecoop/iecoop.hpp>

using namespace iecoop;
int main() {
#ifdef IECOOP_COMPILE_FAIL
  const WORD wYear = 2026;
#else
  const UINT wYear = 2026;
#endif
  const DATE d = CONCAT_DATE(wYear, 11, 23);
  return d.count() > 0 ? 0 : 1;
}
