// EXPECT: ST converts the type spelled in `From` into the one spelled in `To` only explicitly
// EXPECT: spelled<'D', 'A', 'T', 'E'>
// A DATE is no number: DATE_TO_UDINT says which number is meant (seconds since 1970).
#include <iecoop/iecoop.hpp>

using namespace iecoop;
int main() {
  const DATE dToday = "D#2026-11-23"_iec;
  UDINT udiSeconds;
#ifdef IECOOP_COMPILE_FAIL
  udiSeconds = dToday;
#else
  udiSeconds = DATE_TO_UDINT(dToday);
#endif
  return udiSeconds > 0U ? 0 : 1;
}
