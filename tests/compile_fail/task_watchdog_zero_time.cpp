// EXPECT: iecoop: a watchdog time must be greater than zero
#include <iecoop/runtime/task.hpp>
#include <iecoop/types/literals.hpp>

using namespace iecoop;
struct PLC_PRG : program<PLC_PRG> {
  void body() {}
};
int main() {
#ifdef IECOOP_COMPILE_FAIL
  const task<PLC_PRG> main_task{"Main", cyclic{"T#10ms"_iec}, 1, watchdog{"T#0ms"_iec, 2}};
#else
  const task<PLC_PRG> main_task{"Main", cyclic{"T#10ms"_iec}, 1, watchdog{"T#20ms"_iec, 2}};
#endif
  return main_task.settings().has_watchdog ? 0 : 1;
}
