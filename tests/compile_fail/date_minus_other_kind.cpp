// EXPECT: ST subtracts from a point in time only a point of its own kind
// DT - DATE mixes two kinds of point; convert one first.
#include <iecoop/iecoop.hpp>

using namespace iecoop;
int main() {
  const DT dtNow = "DT#2026-11-23-12:30:00"_iec;
  const DATE dToday = "D#2026-11-23"_iec;
#ifdef IECOOP_COMPILE_FAIL
  const TIME tSinceMidnight = dtNow - dToday;
#else
  const TIME tSinceMidnight = dtNow - DATE_TO_DT(dToday);
#endif
  return tSinceMidnight.count() > 0 ? 0 : 1;
}
