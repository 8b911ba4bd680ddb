// EXPECT: iecoop: the application does not list this global variable list \(T\); add it to the application
// EXPECT: globals_get_not_listed.cpp:2[0-9]
// EXPECT: GVL_Plant
// EXPECT-ERRORS: 1
// plc.get<GVL_Plant>() of an application without globals<GVL_Plant>{}: it would fault at run time.
#include <iecoop/pou/global_variables.hpp>
#include <iecoop/runtime/application.hpp>
#include <iecoop/types/literals.hpp>

using namespace iecoop;
struct GVL_Plant : global_variables<GVL_Plant> {
  INT iMode = 1;
};
struct PLC_PRG : program<PLC_PRG> {
  void body() {}
};
int main() {
#ifdef IECOOP_COMPILE_FAIL
  application plc{task<PLC_PRG>{"Main", cyclic{"T#10ms"_iec}, 1}};
  plc.start();
  return plc.get<GVL_Plant>().iMode == 1 ? 0 : 1;
#else
  application plc{task<PLC_PRG>{"Main", cyclic{"T#10ms"_iec}, 1}, globals<GVL_Plant>{}};
  plc.start();
  return plc.get<GVL_Plant>().iMode == 1 ? 0 : 1;
#endif
}
