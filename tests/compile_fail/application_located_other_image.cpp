// EXPECT: iecoop: a located variable of the application's programs or global variable lists lies in another process
// image A program's located variable must lie in the image the application latches and writes; one in another image
// would never reach the field.
#include <iecoop/runtime/application.hpp>
#include <iecoop/types/literals.hpp>

using namespace iecoop;
struct small_tag {};
using small_image = process_image<8, 8, 8, addressing::codesys, small_tag>;
struct LAMP_PRG : program<LAMP_PRG> {
#ifdef IECOOP_COMPILE_FAIL
  [[no_unique_address]] located<BOOL, "%QX0.0"> bLamp;  // the default image
#else
  [[no_unique_address]] located<BOOL, "%QX0.0", small_image> bLamp;
#endif
  using LOCATED = pins<&LAMP_PRG::bLamp>;
  void body() { bLamp = TRUE; }
};
int main() {
  application plc{task<LAMP_PRG>{"Main", cyclic{"T#10ms"_iec}, 1}, use_image<small_image>{}};
  plc.start();
  plc.run_for("T#10ms"_iec);
  return 0;
}
