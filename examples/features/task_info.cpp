// One feature: task information inside blocks. A ramp block ported from a TwinCAT library
// reads its task's cycle time (`_TaskInfo[GETCURTASKINDEXEX()].CycleTime`, in 100 ns), so one
// block ramps at the same rate in a 10 ms task and in a 50 ms task. A monitor reads the rest in
// iecoop's names: current_task() is the task whose cycle runs the code (CODESYS's
// __CURRENTTASK), with its cycle number, first-cycle flag, the previous cycle's execution time
// and whether the task overran; outside a cycle it is no task.
#include <fmt/core.h>

#include <iecoop/fmt.hpp>
#include <iecoop/iecoop.hpp>

using namespace iecoop;

// FUNCTION_BLOCK FB_Ramp                  (the rate is per second, whatever the task's interval)
struct FB_Ramp : function_block<FB_Ramp> {
  // VAR_INPUT
  REAL rTarget;  // rTarget : REAL;
  REAL rRate;    // rRate : REAL;   (per second)
  // END_VAR
  // VAR_OUTPUT
  REAL rOut;     // rOut : REAL;
  // END_VAR
  // VAR
  REAL rStep;    // rStep : REAL;
  // END_VAR
  using VAR_INPUT = pins<&FB_Ramp::rTarget, &FB_Ramp::rRate>;
  using VAR_OUTPUT = pins<&FB_Ramp::rOut>;

  void body() {
    // rStep := rRate * UDINT_TO_REAL(_TaskInfo[GETCURTASKINDEXEX()].CycleTime) / 1.0E7;
    rStep = rRate * UDINT_TO_REAL(F_GetTaskInfo().CycleTime) / 1.0E7f;
    rOut = MIN(rOut + rStep, rTarget);  // rOut := MIN(rOut + rStep, rTarget);
  }
};

// PROGRAM FAST_PRG / SLOW_PRG: the same block, in two tasks
struct FAST_PRG : program<FAST_PRG> {
  FB_Ramp fbRamp;  // VAR fbRamp : FB_Ramp; END_VAR
  void body() {
    fbRamp("rTarget"_ = 1.0f, "rRate"_ = 2.0f);  // fbRamp(rTarget := 1.0, rRate := 2.0);
  }
};
struct SLOW_PRG : program<SLOW_PRG> {
  FB_Ramp fbRamp;  // VAR fbRamp : FB_Ramp; END_VAR
  void body() {
    fbRamp("rTarget"_ = 1.0f, "rRate"_ = 2.0f);  // fbRamp(rTarget := 1.0, rRate := 2.0);
  }
};

// FUNCTION_BLOCK FB_TaskMonitor: what its task tells it
struct FB_TaskMonitor : function_block<FB_TaskMonitor> {
  void body() {
    const task_info& t = current_task();             // CODESYS: __CURRENTTASK.pTaskInfo^
    const PlcTaskSystemInfo info = F_GetTaskInfo();  // TwinCAT: _TaskInfo[GETCURTASKINDEXEX()]
    fmt::print("  {} (index {}, TwinCAT {}) cycle {} at {}: first {}, last exec {} ({} x 100 ns), overran {}\n",
               t.name(), t.index(), GETCURTASKINDEXEX(), t.cycle_number(), TIME(t.cycle_start()),
               BOOL(t.first_cycle()), TIME(t.last_exec_time()), info.LastExecTime, info.CycleTimeExceeded);
  }
};

// PROGRAM LOG_PRG
struct LOG_PRG : program<LOG_PRG> {
  FB_TaskMonitor fbMonitor;  // VAR fbMonitor : FB_TaskMonitor; END_VAR
  void body() { fbMonitor(); }
};

int main() {
  {
    // TASK Fast(INTERVAL := T#10ms, PRIORITY := 1);   PROGRAM Fast_Prg WITH Fast : FAST_PRG;
    // TASK Slow(INTERVAL := T#50ms, PRIORITY := 5);   PROGRAM Slow_Prg WITH Slow : SLOW_PRG;
    application plc{
        task<FAST_PRG>{"Fast", cyclic{"T#10ms"_iec}, 1},
        task<SLOW_PRG>{"Slow", cyclic{"T#50ms"_iec}, 5},
    };
    plc.start();
    fmt::print("one ramp block, 2.0 per second, in two tasks:\n");
    for (const TIME until : {"T#100ms"_iec, "T#300ms"_iec, "T#500ms"_iec}) {
      plc.run_until(LTIME(until));
      fmt::print("  at {:<7}  Fast (T#10ms): {:.2f}   Slow (T#50ms): {:.2f}\n", TIME(plc.now()),
                 FAST_PRG::instance().fbRamp.rOut, SLOW_PRG::instance().fbRamp.rOut);
    }
    plc.stop();
  }
  {
    // TASK Log(INTERVAL := T#20ms, PRIORITY := 10);   PROGRAM Log_Prg WITH Log : LOG_PRG;
    application plc{task<LOG_PRG>{"Log", cyclic{"T#20ms"_iec}, 10}};
    // Cycle n takes 3 ms, but cycle 2 takes 25 ms: the release at 60 ms finds it under way.
    plc.task("Log").model_execution_time([](std::uint64_t n, void*) { return LTIME(n == 2 ? "T#25ms"_iec : "T#3ms"_iec); });
    plc.start();
    fmt::print("a monitor in a 20 ms task whose third cycle takes 25 ms:\n");
    plc.run_for("T#100ms"_iec);
    plc.stop();
  }
  // Outside a task cycle: no task.
  fmt::print("in main: current_task().index() = {}, GETCURTASKINDEXEX() = {}\n", current_task().index(),
             GETCURTASKINDEXEX());
}
