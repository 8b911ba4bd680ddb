// EXPECT: ST converts the type spelled in `From` into the one spelled in `To` only explicitly
// EXPECT: spelled<'D', 'T'>
// A DT into a DATE drops the time of day: DT_TO_DATE says so.
#include <iecoop/iecoop.hpp>

using namespace iecoop;
int main() {
  const DT dtNow = "DT#2026-11-23-12:30:00"_iec;
  DATE dToday;
#ifdef IECOOP_COMPILE_FAIL
  dToday = dtNow;
#else
  dToday = DT_TO_DATE(dtNow);
#endif
  return dToday.count() > 0 ? 0 : 1;
}
