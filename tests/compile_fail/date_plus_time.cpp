// EXPECT: ST adds to a point in time only a duration, and only to TOD and DT
// CODESYS's ADD has no DATE + TIME: the sum is a DT, computed from one.
#include <iecoop/iecoop.hpp>

using namespace iecoop;
int main() {
  const DATE dStart = "D#2026-11-23"_iec;
#ifdef IECOOP_COMPILE_FAIL
  const DATE dLater = dStart + "T#1d"_iec;
  return dLater.count() > 0 ? 0 : 1;
#else
  const DT dtLater = DATE_TO_DT(dStart) + "T#1d"_iec;
  return dtLater.count() > 0 ? 0 : 1;
#endif
}
