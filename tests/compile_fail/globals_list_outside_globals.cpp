// EXPECT: iecoop: a global variable list is given to the application outside globals<...>
// EXPECT: globals_list_outside_globals.cpp:1[0-9]
// EXPECT: GVL_Plant
// EXPECT-ERRORS: 1
// `application plc{task<...>{...}, GVL_Plant{}}`: a list is given in globals<GVL_Plant>{}.
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
  application plc{task<PLC_PRG>{"Main", cyclic{"T#10ms"_iec}, 1}, GVL_Plant{}};
#else
  application plc{task<PLC_PRG>{"Main", cyclic{"T#10ms"_iec}, 1}, globals<GVL_Plant>{}};
#endif
  plc.start();
  return 0;
}
