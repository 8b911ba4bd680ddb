// EXPECT: iecoop: a program's VAR_EXTERNAL names the global variable lists it uses as globals<...>
// EXPECT: globals_external_not_globals.cpp:2[0-9]
// EXPECT-ERRORS: 1
// VAR_EXTERNAL given as the list itself instead of globals<GVL_Plant>.
#include <iecoop/pou/global_variables.hpp>
#include <iecoop/runtime/application.hpp>
#include <iecoop/types/literals.hpp>

using namespace iecoop;
struct GVL_Plant : global_variables<GVL_Plant> {
  INT iMode = 1;
};
struct MODE_PRG : program<MODE_PRG> {
#ifdef IECOOP_COMPILE_FAIL
  using VAR_EXTERNAL = GVL_Plant;
#else
  using VAR_EXTERNAL = globals<GVL_Plant>;
#endif
  void body() { GVL_Plant::instance().iMode = 2; }
};
int main() {
  application plc{task<MODE_PRG>{"Main", cyclic{"T#10ms"_iec}, 1}, globals<GVL_Plant>{}};
  plc.start();
  return 0;
}
