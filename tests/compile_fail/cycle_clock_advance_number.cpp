// EXPECT: iecoop: a duration is a TIME, an LTIME or a std::chrono duration of whole nanoseconds, not a bare number
// EXPECT: cycle_clock_advance_number\.cpp:13:
// EXPECT-ERRORS: 1
// The cycle clock moves on by a duration: advance(2000) would be LTIME's 2 µs, and the timer
// would never reach its T#2s.
#include <iecoop/iecoop.hpp>
using namespace iecoop;
int main() {
  TON tmr;
  cycle_clock::set(LTIME{});
  tmr("IN"_ = TRUE, "PT"_ = "T#2s"_iec);
#ifdef IECOOP_COMPILE_FAIL
  cycle_clock::advance(2000);
#else
  cycle_clock::advance("T#2s"_iec);
#endif
  tmr();
  return tmr.Q ? 0 : 1;
}
