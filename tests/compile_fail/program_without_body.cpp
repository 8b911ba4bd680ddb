// EXPECT: a PROGRAM needs its code as `void body\(\)`
// EXPECT: PRG_Main
// EXPECT-ERRORS: 1
// Calling a PROGRAM that has no body says so, naming the PROGRAM, in one error.
#include <iecoop/iecoop.hpp>
using namespace iecoop;
struct PRG_Main : program<PRG_Main> {
  INT iCycles;
#ifndef IECOOP_COMPILE_FAIL
  void body() { iCycles = iCycles + 1; }
#endif
};
int main() {
  PRG_Main main_program;
  main_program();
  return main_program.iCycles == 1 ? 0 : 1;
}
