// EXPECT: iecoop: a %I\.\.\. located variable is an input, written by the I/O driver
// An input (%I) is written by the I/O driver at the start of each task cycle; the program
// only reads it. Outputs (%Q) and memory (%M) are assigned like variables.
#include <iecoop/io/located.hpp>
using namespace iecoop;
struct GVL_IO {
  [[no_unique_address]] located<BOOL, "%IX0.5"> bStart;
  [[no_unique_address]] located<BOOL, "%QX0.0"> bMotor;
};
int main() {
  GVL_IO io;
#ifdef IECOOP_COMPILE_FAIL
  io.bStart = TRUE;  // bStart := TRUE;  (bStart AT %IX0.5)
#else
  io.bMotor = io.bStart;  // bMotor := bStart;  (bMotor AT %QX0.0)
#endif
  return io.bMotor ? 1 : 0;
}
