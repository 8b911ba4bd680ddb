// EXPECT: iecoop: a task calls PROGRAMs
// As in CODESYS, a task calls programs; function blocks are called from a program.
#include <iecoop/runtime/task.hpp>
#include <iecoop/types/literals.hpp>

using namespace iecoop;
struct FB_Motor : function_block<FB_Motor> {
  void body() {}
};
struct PLC_PRG : program<PLC_PRG> {
  FB_Motor motor;
  void body() { motor(); }
};
int main() {
#ifdef IECOOP_COMPILE_FAIL
  const task<FB_Motor> main_task{"Main", cyclic{"T#10ms"_iec}, 1};
#else
  const task<PLC_PRG> main_task{"Main", cyclic{"T#10ms"_iec}, 1};
#endif
  return main_task.settings().priority == 1 ? 0 : 1;
}
