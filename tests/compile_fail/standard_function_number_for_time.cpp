// EXPECT: iecoop: a C\+\+ value given to a standard function must be a number that the other inputs' IEC
// A C++ number beside a TIME is no TIME: write the TIME literal.
#include <iecoop/iecoop.hpp>
using namespace iecoop;
int main() {
  TIME tWait = "T#2s"_iec;
#ifdef IECOOP_COMPILE_FAIL
  TIME tAtLeast = MAX(tWait, 500);
#else
  TIME tAtLeast = MAX(tWait, "T#500ms"_iec);
#endif
  (void)tAtLeast;
}
