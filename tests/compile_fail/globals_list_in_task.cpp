// EXPECT: iecoop: a task calls PROGRAMs, and a global variable list is none
// EXPECT: globals_list_in_task.cpp:1[0-9]
// EXPECT: GVL_Plant
// EXPECT-ERRORS: 1
// `task<PLC_PRG, GVL_Plant>{...}`: a list is not called by a task; it is given in globals<GVL_Plant>{}.
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
  application plc{task<PLC_PRG, GVL_Plant>{"Main", cyclic{"T#10ms"_iec}, 1}};
#else
  application plc{task<PLC_PRG>{"Main", cyclic{"T#10ms"_iec}, 1}, globals<GVL_Plant>{}};
#endif
  plc.start();
  return 0;
}
