// One feature: faults. A task's watchdog sees a cycle that takes too long and reports it to
// the fault handler; the application stops in the exception state until a reset, as a PLC
// does. A test installs its own handler to see the fault instead of aborting.
#include <fmt/core.h>

#include <iecoop/fmt.hpp>
#include <iecoop/iecoop.hpp>

using namespace iecoop;

// PROGRAM PLC_PRG
struct PLC_PRG : program<PLC_PRG> {
  UDINT udiCycles;  // VAR udiCycles : UDINT; END_VAR
  void body() {
    udiCycles = udiCycles + 1;  // udiCycles := udiCycles + 1;
  }
};

void on_fault(const fault_info& f) {
  fmt::print("fault handler: {}: {}\n", to_string(f.kind), f.message);
}

int main() {
  set_fault_handler(&on_fault);
  // Task configuration: Main: Cyclic, t#10ms, priority 1; Watchdog: time t#5ms, sensitivity 1
  application plc{task<PLC_PRG>{"Main", cyclic{"T#10ms"_iec}, 1, watchdog{"T#5ms"_iec, 1}}};
  plc.start();
  plc.task("Main").model_execution_time("T#3ms"_iec);  // within the watchdog time
  plc.run_for("T#50ms"_iec);
  fmt::print("at {}: {} cycles, no fault\n", TIME(plc.now()), plc.get<PLC_PRG>().udiCycles);

  plc.task("Main").model_execution_time("T#7ms"_iec);  // now a cycle overruns the watchdog
  plc.run_for("T#50ms"_iec);
  if (plc.faulted_task() != nullptr) {
    fmt::print("at {}: stopped in the exception state by task {} after {} cycles\n", TIME(plc.now()),
               plc.faulted_task()->name(), plc.get<PLC_PRG>().udiCycles);
  }

  plc.reset(reset_kind::warm);  // Online: Reset warm
  plc.task("Main").model_execution_time("T#3ms"_iec);
  plc.start();
  plc.run_for("T#50ms"_iec);
  fmt::print("after reset warm and start: {} cycles, in exception {}\n", plc.get<PLC_PRG>().udiCycles,
             BOOL(plc.faulted_task() != nullptr));
  plc.stop();
}
