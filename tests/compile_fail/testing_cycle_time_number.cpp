// EXPECT: iecoop: a duration is a TIME, an LTIME or a std::chrono duration of whole nanoseconds, not a bare number
// EXPECT: testing_cycle_time_number\.cpp:12:
// EXPECT-ERRORS: 1
// The cycle time of testing::cycles is a duration too: 10 is no T#10ms. std::chrono's
// literals carry their unit, so they are durations.
#include <iecoop/testing.hpp>
using namespace iecoop;
using namespace std::chrono_literals;
void every_ten_milliseconds() {
  TON tmr;
#ifdef IECOOP_COMPILE_FAIL
  testing::cycles run{tmr, 10};
#else
  testing::cycles run{tmr, 10ms};
#endif
  run.step();
}
