// One feature: the task configuration. Two cyclic tasks with priorities call their programs;
// simulated time runs a second of the controller in a moment, deterministically: the same
// cycles, the same order, the same statistics on every run.
#include <fmt/core.h>

#include <iecoop/fmt.hpp>
#include <iecoop/iecoop.hpp>

using namespace iecoop;

// VAR_GLOBAL diFastCycles : DINT; END_VAR
DINT diFastCycles;

// PROGRAM FAST_PRG
struct FAST_PRG : program<FAST_PRG> {
  void body() {
    diFastCycles = diFastCycles + 1;  // diFastCycles := diFastCycles + 1;
  }
};

// PROGRAM SLOW_PRG
struct SLOW_PRG : program<SLOW_PRG> {
  DINT diSeen;  // VAR diSeen : DINT; END_VAR
  void body() {
    diSeen = diFastCycles;  // diSeen := diFastCycles;
    if (TIME(system_time) < "T#100ms"_iec) {
      fmt::print("  {:<7} SLOW_PRG sees diFastCycles = {}\n", TIME(system_time), diSeen);
    }
  }
};

int main() {
  // TASK Fast(INTERVAL := T#10ms, PRIORITY := 1);   PROGRAM Fast_Prg WITH Fast : FAST_PRG;
  // TASK Slow(INTERVAL := T#30ms, PRIORITY := 5);   PROGRAM Slow_Prg WITH Slow : SLOW_PRG;
  application plc{
      task<FAST_PRG>{"Fast", cyclic{"T#10ms"_iec}, 1},
      task<SLOW_PRG>{"Slow", cyclic{"T#30ms"_iec}, 5},
  };
  plc.task("Fast").model_execution_time("T#2ms"_iec);   // each Fast cycle takes 2 ms of CPU,
  plc.task("Slow").model_execution_time("T#12ms"_iec);  // each Slow cycle 12 ms

  plc.start();
  fmt::print("the first 100 ms: Slow starts after Fast's cycle (Fast has the higher priority):\n");
  plc.run_for("T#1s"_iec);
  fmt::print("after {}:\n", TIME(plc.now()));
  for (const char* name : {"Fast", "Slow"}) {
    const task_statistics& s = plc.task(name).statistics();
    fmt::print("  {:<4} cycles {:>3}  cycle time last {} max {}  jitter max {}\n", name, s.cycles,
               s.last_cycle_time, s.max_cycle_time, s.max_jitter);
  }
  fmt::print("Slow waits 2 ms for Fast at each start (its jitter), and Fast preempts it once\n"
             "in each cycle: 12 ms of its own work take 14 ms.\n");
  plc.stop();
}
