// EXPECT: iecoop: a cyclic task needs an interval greater than zero
// A cyclic task of interval 0 would run endlessly at one instant.
#include <iecoop/runtime/task.hpp>
#include <iecoop/types/literals.hpp>

using namespace iecoop;
struct PLC_PRG : program<PLC_PRG> {
  void body() {}
};
int main() {
#ifdef IECOOP_COMPILE_FAIL
  const task<PLC_PRG> main_task{"Main", cyclic{"T#0ms"_iec}, 1};
#else
  const task<PLC_PRG> main_task{"Main", cyclic{"T#1ms"_iec}, 1};
#endif
  return main_task.settings().priority == 1 ? 0 : 1;
}
