// EXPECT: iecoop: a task calls at least one program
// A task with nothing to call is a configuration mistake.
#include <iecoop/runtime/task.hpp>
#include <iecoop/types/literals.hpp>

using namespace iecoop;
struct PLC_PRG : program<PLC_PRG> {
  void body() {}
};
int main() {
#ifdef IECOOP_COMPILE_FAIL
  const task<> main_task{"Main", cyclic{"T#10ms"_iec}, 1};
#else
  const task<PLC_PRG> main_task{"Main", cyclic{"T#10ms"_iec}, 1};
#endif
  return main_task.settings().priority == 1 ? 0 : 1;
}
