// EXPECT: ST adds to a point in time only a duration, and only to TOD and DT
// EXPECT: spelled<'D', 'A', 'T', 'E'>
// CODESYS's ADD takes TOD + TIME and DT + TIME; a sum of two dates means nothing.
#include <iecoop/iecoop.hpp>

using namespace iecoop;
int main() {
  const DATE dStart = "D#2026-11-23"_iec;
  const DATE dOther = "D#2026-11-24"_iec;
#ifdef IECOOP_COMPILE_FAIL
  const DATE dSum = dStart + dOther;
  return dSum.count() > 0 ? 0 : 1;
#else
  const TIME tBetween = dOther - dStart;
  return tBetween.count() > 0 ? 0 : 1;
#endif
}
