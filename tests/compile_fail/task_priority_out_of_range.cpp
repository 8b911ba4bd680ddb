// EXPECT: iecoop: a task priority is 0 \(highest\) to 31 \(lowest\)
// A CODESYS task priority is 0..31; anything else is rejected while compiling.
#include <iecoop/runtime/application.hpp>
#include <iecoop/types/literals.hpp>

using namespace iecoop;
struct PLC_PRG : program<PLC_PRG> {
  void body() {}
};
int main() {
#ifdef IECOOP_COMPILE_FAIL
  application plc{task<PLC_PRG>{"Main", cyclic{"T#10ms"_iec}, 32}};
#else
  application plc{task<PLC_PRG>{"Main", cyclic{"T#10ms"_iec}, 31}};
#endif
  plc.start();
  plc.run_for("T#10ms"_iec);
  return plc.task(0).statistics().cycles == 1 ? 0 : 1;
}
