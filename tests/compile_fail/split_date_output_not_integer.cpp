// EXPECT: the outputs of SPLIT_DATE, SPLIT_TOD and SPLIT_DT are integer variables \(ANY_INT\)
// IEC's SPLIT_DATE writes ANY_INT outputs; a REAL is none.
#include <iecoop/iecoop.hpp>

using namespace iecoop;
int main() {
  INT iYear;
  INT iMonth;
#ifdef IECOOP_COMPILE_FAIL
  REAL rDay;
#else
  INT rDay;
#endif
  SPLIT_DATE("D#2026-11-23"_iec, iYear, iMonth, rDay);
  return iYear == 2026 ? 0 : 1;
}
