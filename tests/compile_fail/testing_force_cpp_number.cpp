// EXPECT: iecoop: a forced value is a value of the variable's IEC type, not a C[+][+] number
// The test kit forces a value of the variable's type: INT(11), as ST's literal is typed by the
// variable it goes to.
#include <iecoop/testing.hpp>
using namespace iecoop;
void force_count() {
  INT iCount;
  testing::cycles run{[&] { iCount += 1; }};
#ifdef IECOOP_COMPILE_FAIL
  run.force(iCount, 11);
#else
  run.force(iCount, INT(11));
#endif
  run.step();
}
