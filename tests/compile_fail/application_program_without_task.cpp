// EXPECT: iecoop: a PROGRAM is assigned to no task
// EXPECT: application_program_without_task.cpp:1[0-9]
// EXPECT: LOG_PRG
// EXPECT-ERRORS: 1
// IEC's `PROGRAM Log : LOG_PRG;` without `WITH <task>`: the application would own a program
// that never runs. Name it in a task.
#include <iecoop/runtime/application.hpp>
#include <iecoop/types/literals.hpp>

using namespace iecoop;
struct PLC_PRG : program<PLC_PRG> {
  void body() {}
};
struct LOG_PRG : program<LOG_PRG> {
  void body() {}
};
int main() {
#ifdef IECOOP_COMPILE_FAIL
  application plc{task<PLC_PRG>{"Main", cyclic{"T#10ms"_iec}, 1}, LOG_PRG{}};
#else
  application plc{task<PLC_PRG>{"Main", cyclic{"T#10ms"_iec}, 1}, task<LOG_PRG>{"Log", cyclic{"T#100ms"_iec}, 20}};
#endif
  plc.start();
  return 0;
}
