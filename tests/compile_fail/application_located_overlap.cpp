// EXPECT: iecoop: two located variables overlap
// The application checks the located variables of all its programs and global variable
// lists together: here two programs drive the same output bit (%QW0 contains %QX1.2).
#include <iecoop/runtime/application.hpp>
#include <iecoop/types/literals.hpp>

using namespace iecoop;
struct MOTOR_PRG : program<MOTOR_PRG> {
  [[no_unique_address]] located<WORD, "%QW0"> wMotorWord;
  using LOCATED = pins<&MOTOR_PRG::wMotorWord>;
  void body() { wMotorWord = WORD(1); }
};
struct LAMP_PRG : program<LAMP_PRG> {
#ifdef IECOOP_COMPILE_FAIL
  [[no_unique_address]] located<BOOL, "%QX1.2"> bLamp;
#else
  [[no_unique_address]] located<BOOL, "%QX2.2"> bLamp;
#endif
  using LOCATED = pins<&LAMP_PRG::bLamp>;
  void body() { bLamp = TRUE; }
};
int main() {
  application plc{task<MOTOR_PRG>{"Fast", cyclic{"T#1ms"_iec}, 0}, task<LAMP_PRG>{"Slow", cyclic{"T#10ms"_iec}, 5}};
  plc.start();
  plc.run_for("T#10ms"_iec);
  return 0;
}
