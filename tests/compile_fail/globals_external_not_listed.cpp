// EXPECT: iecoop: a program uses a global variable list \(its VAR_EXTERNAL\) that the application does not list
// EXPECT: globals_external_not_listed.cpp:2[0-9]
// EXPECT: GVL_Plant
// EXPECT-ERRORS: 1
// MODE_PRG names the lists it uses (ST's VAR_EXTERNAL); the application lacks GVL_Plant.
#include <iecoop/pou/global_variables.hpp>
#include <iecoop/runtime/application.hpp>
#include <iecoop/types/literals.hpp>

using namespace iecoop;
struct GVL_Plant : global_variables<GVL_Plant> {
  INT iMode = 1;
  BOOL bAuto;
};
struct MODE_PRG : program<MODE_PRG> {
  using VAR_EXTERNAL = globals<GVL_Plant>;  // VAR_EXTERNAL: the lists it uses
  void body() {
    if (GVL_Plant::instance().bAuto) GVL_Plant::instance().iMode = 2;
  }
};
int main() {
#ifdef IECOOP_COMPILE_FAIL
  application plc{task<MODE_PRG>{"Main", cyclic{"T#10ms"_iec}, 1}};
#else
  application plc{task<MODE_PRG>{"Main", cyclic{"T#10ms"_iec}, 1}, globals<GVL_Plant>{}};
#endif
  plc.start();
  return 0;
}
