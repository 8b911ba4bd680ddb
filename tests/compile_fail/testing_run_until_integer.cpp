// EXPECT: iecoop: run_until waits for a condition: a BOOL variable or a callable
// run_until reads a BOOL variable, or calls a condition; an INT is neither.
#include <iecoop/testing.hpp>
using namespace iecoop;
void wait_for_count() {
  INT iCount;
  testing::cycles run{[&] { iCount += 1; }};
#ifdef IECOOP_COMPILE_FAIL
  static_cast<void>(run.run_until(iCount, "T#1s"_iec));
#else
  static_cast<void>(run.run_until([&] { return iCount == 3; }, "T#1s"_iec));
#endif
}
