// EXPECT: iecoop: a duration is a TIME, an LTIME or a std::chrono duration of whole nanoseconds, not a bare number
// EXPECT: testing_advance_number\.cpp:14:
// EXPECT-ERRORS: 1
// A bare number is no duration: advance(3000) would be LTIME's 3000 ns (one cycle), where its
// writer meant 3 s. ST writes the unit (T#3s), and so does the test.
#include <iecoop/testing.hpp>
using namespace iecoop;
void run_three_seconds() {
  TON tmr;
  testing::cycles run{tmr, "T#10ms"_iec};
  tmr.IN = TRUE;
  tmr.PT = "T#2s"_iec;
#ifdef IECOOP_COMPILE_FAIL
  run.advance(3000);
#else
  run.advance("T#3s"_iec);
#endif
}
