// Firmware example: an application with three tasks, run by iecoop's scheduler and driven by
// the SysTick — a pump started and stopped by push buttons, behind an INTERFACE, with a
// star-delta starter timed by a TON, a start counter (CTU) and a blinking lamp (TP).
//
//   Tasks   Fast   cyclic T#1ms    priority 0   MOTOR_PRG  buttons, latch, motor
//           Slow   cyclic T#10ms   priority 5   STATS_PRG  starts (CTU) and running time
//           Blink  cyclic T#100ms  priority 10  LAMP_PRG   lamp blinks while the pump is off
//
// The field is simulated by the I/O driver: an operator presses START at 20 ms and 700 ms and
// STOP at 520 ms and 900 ms. After one second of machine time main() prints what the field
// saw, what a block that all three programs call saw of its tasks (task information, read as
// a block ported from TwinCAT reads it) and the task statistics, and checks them.
//
// Every tick (1 ms) the main loop runs the application for one millisecond; the SysTick
// interrupt only counts ticks (embedded/tick.hpp). The application has static storage and a
// process image of one input and one output byte, and keeps no retain memory: its RAM is
// what the size table of docs/embedded.md reports.
#include <cstdint>

#include <iecoop/iecoop.hpp>

#include "console.hpp"
#include "exit_status.hpp"
#include "fault_handler.hpp"
#include "tick.hpp"

namespace {

using namespace iecoop;

// The process image: %IB0 and %QB0 only, no %M (the default image has 64 + 64 + 256 bytes).
struct pump_image_tag {};
using pump_image = process_image<1, 1, 0, addressing::codesys, pump_image_tag>;

// INTERFACE I_Motor
struct I_Motor : interface_base<I_Motor> {
  // METHOD Run
  // VAR_INPUT bRun : BOOL; END_VAR
  struct Run_vars {
    BOOL bRun;
  };
  virtual void Run(args<Run_vars> in) = 0;
  // PROPERTY bRunning : BOOL   (Get only: TRUE once the motor turns at full voltage)
  virtual BOOL bRunning_Get() = 0;
  [[no_unique_address]] property<BOOL, &I_Motor::bRunning_Get> bRunning{this};
};

// FUNCTION_BLOCK FB_StarDelta IMPLEMENTS I_Motor
// Starts in star, switches to delta after T#50ms.
struct FB_StarDelta : function_block<FB_StarDelta, implements<I_Motor>> {
  // VAR
  TON tStar;    // tStar : TON;
  BOOL bStar;   // bStar : BOOL;
  BOOL bDelta;  // bDelta : BOOL;
  // END_VAR

  void Run(args<Run_vars> in) override {
    tStar("IN"_ = in.bRun, "PT"_ = "T#50ms"_iec);  // tStar(IN := bRun, PT := T#50ms);
    bStar = in.bRun && !tStar.Q;                   // bStar := bRun AND NOT tStar.Q;
    bDelta = tStar.Q;                              // bDelta := tStar.Q;
  }
  BOOL bRunning_Get() override { return bDelta; }  // bRunning := bDelta;
};

// FUNCTION_BLOCK FB_TaskProbe: notes, per task, what the task that calls it tells it
struct FB_TaskProbe : function_block<FB_TaskProbe> {
  // VAR_OUTPUT
  ARRAY<STRING<15>, 1, 3> asTask;  // asTask : ARRAY[1..3] OF STRING(15);   (by task index)
  ARRAY<TIME, 1, 3> atInterval;    // atInterval : ARRAY[1..3] OF TIME;
  ARRAY<UDINT, 1, 3> audiCycles;   // audiCycles : ARRAY[1..3] OF UDINT;
  // END_VAR

  void body() {
    const DINT i = GETCURTASKINDEXEX();                      // i := GETCURTASKINDEXEX();
    const PlcTaskSystemInfo info = F_GetTaskInfo();          // info := _TaskInfo[i];
    asTask[i] = info.TaskName;                               // asTask[i] := info.TaskName;
    atInterval[i] = UDINT_TO_TIME(info.CycleTime / 10000U);  // atInterval[i] := UDINT_TO_TIME(info.CycleTime / 10000);
    audiCycles[i] = info.CycleCount;                         // audiCycles[i] := info.CycleCount;
  }
};

// VAR_GLOBAL fbProbe : FB_TaskProbe; END_VAR   (each program calls it: it sees each task in turn)
FB_TaskProbe fbProbe;

// PROGRAM MOTOR_PRG
struct MOTOR_PRG : program<MOTOR_PRG> {
  // VAR
  [[no_unique_address]] located<BOOL, "%IX0.0", pump_image> ixStart;  // ixStart AT %IX0.0 : BOOL;
  [[no_unique_address]] located<BOOL, "%IX0.1", pump_image> ixStop;   // ixStop AT %IX0.1 : BOOL;
  [[no_unique_address]] located<BOOL, "%QX0.0", pump_image> qxStar;   // qxStar AT %QX0.0 : BOOL;
  [[no_unique_address]] located<BOOL, "%QX0.1", pump_image> qxDelta;  // qxDelta AT %QX0.1 : BOOL;
  FB_StarDelta fbStarter;                                             // fbStarter : FB_StarDelta;
  itf<I_Motor> ipMotor;                                               // ipMotor : I_Motor;
  BOOL bRun;                                                          // bRun : BOOL;
  BOOL bRunning;                                                      // bRunning : BOOL;
  // END_VAR
  using LOCATED = pins<&MOTOR_PRG::ixStart, &MOTOR_PRG::ixStop, &MOTOR_PRG::qxStar, &MOTOR_PRG::qxDelta>;

  void body() {
    fbProbe();                            // fbProbe();
    ipMotor = fbStarter;                  // ipMotor := fbStarter;
    bRun = (ixStart || bRun) && !ixStop;  // bRun := (ixStart OR bRun) AND NOT ixStop;
    ipMotor->Run(bRun);                   // ipMotor.Run(bRun);
    bRunning = ipMotor->bRunning;         // bRunning := ipMotor.bRunning;
    qxStar = fbStarter.bStar;             // qxStar := fbStarter.bStar;
    qxDelta = fbStarter.bDelta;           // qxDelta := fbStarter.bDelta;
  }
};

// PROGRAM STATS_PRG
struct STATS_PRG : program<STATS_PRG> {
  // VAR
  CTU ctStarts;   // ctStarts : CTU;
  TIME tRunning;  // tRunning : TIME;
  // END_VAR

  void body() {
    fbProbe();  // fbProbe();
    const BOOL bRunning = MOTOR_PRG::instance().bRunning;
    ctStarts("CU"_ = bRunning, "RESET"_ = FALSE, "PV"_ = WORD(100));  // ctStarts(CU := MOTOR_PRG.bRunning, PV := 100);
    // IF MOTOR_PRG.bRunning THEN      (the task's interval: TwinCAT's CycleTime is in 100 ns)
    //     tRunning := tRunning + UDINT_TO_TIME(_TaskInfo[GETCURTASKINDEXEX()].CycleTime / 10000);
    // END_IF
    if (bRunning) {
      tRunning = tRunning + UDINT_TO_TIME(F_GetTaskInfo().CycleTime / 10000U);
    }
  }
};

// PROGRAM LAMP_PRG
struct LAMP_PRG : program<LAMP_PRG> {
  // VAR
  [[no_unique_address]] located<BOOL, "%QX0.2", pump_image> qxLamp;  // qxLamp AT %QX0.2 : BOOL;
  TP tpBlink;                                                        // tpBlink : TP;
  BOOL bToggle;                                                      // bToggle : BOOL;
  // END_VAR
  using LOCATED = pins<&LAMP_PRG::qxLamp>;

  void body() {
    fbProbe();                                              // fbProbe();
    bToggle = !bToggle;                                     // bToggle := NOT bToggle;
    tpBlink("IN"_ = bToggle, "PT"_ = "T#50ms"_iec);         // tpBlink(IN := bToggle, PT := T#50ms);
    qxLamp = tpBlink.Q && !MOTOR_PRG::instance().bRunning;  // qxLamp := tpBlink.Q AND NOT MOTOR_PRG.bRunning;
  }
};

// The simulated field: an operator's push buttons on %IB0, and a record of %QB0.
struct pump_field {
  std::uint32_t now_ms = 0;  // set by the main loop before each millisecond runs
  std::uint32_t star_on_ms = 0, delta_on_ms = 0, lamp_on_ms = 0;
  std::uint32_t delta_starts = 0;
  std::byte last_outputs{};

  void read_inputs(std::span<std::byte> inputs) const {
    const auto pressed = [this](std::uint32_t from) { return now_ms >= from && now_ms < from + 20U; };
    const bool start = pressed(20) || pressed(700);
    const bool stop = pressed(520) || pressed(900);
    inputs[0] = std::byte((start ? 0x01U : 0U) | (stop ? 0x02U : 0U));
  }
  void write_outputs(std::span<const std::byte> outputs) {
    const std::byte changed = outputs[0] ^ last_outputs;
    if ((changed & outputs[0] & std::byte{0x02}) != std::byte{0}) ++delta_starts;
    if ((outputs[0] & std::byte{0x01}) != std::byte{0}) star_on_ms = now_ms;
    if ((outputs[0] & std::byte{0x02}) != std::byte{0}) delta_on_ms = now_ms;
    if ((outputs[0] & std::byte{0x04}) != std::byte{0}) lamp_on_ms = now_ms;
    last_outputs = outputs[0];
  }
};

// TASK Fast (INTERVAL := T#1ms, PRIORITY := 0);    PROGRAM Motor WITH Fast : MOTOR_PRG;
// TASK Slow (INTERVAL := T#10ms, PRIORITY := 5);   PROGRAM Stats WITH Slow : STATS_PRG;
// TASK Blink (INTERVAL := T#100ms, PRIORITY := 10); PROGRAM Lamp WITH Blink : LAMP_PRG;
application plc{
    task<MOTOR_PRG>{"Fast", cyclic{"T#1ms"_iec}, 0},
    task<STATS_PRG>{"Slow", cyclic{"T#10ms"_iec}, 5},
    task<LAMP_PRG>{"Blink", cyclic{"T#100ms"_iec}, 10},
    use_image<pump_image>{},
    retain_capacity<0>{},  // no RETAIN variables: no retain memory
};
pump_field field;

void print_task(const task_state& t) {
  const task_statistics& s = t.statistics();
  firmware::print_line("task ", t.name(), ": ", s.cycles, " cycles, ", s.overruns, " overruns");
}

// What fbProbe saw of task i (TwinCAT's index, from 1).
void print_probe(DINT i) {
  const TIME interval = fbProbe.atInterval[i];
  firmware::print_line("fbProbe in task ", i, ": ", fbProbe.asTask[i].c_str(), ", every ", interval, ", cycle ",
                       fbProbe.audiCycles[i]);
}
bool probe_saw(DINT i, const char* name, TIME interval, UDINT cycles) {
  return fbProbe.asTask[i] == name && fbProbe.atInterval[i] == interval && fbProbe.audiCycles[i] == cycles;
}

}  // namespace

#if defined(__arm__)
// The SysTick interrupt: one tick more. Nothing else happens in interrupt context.
extern "C" void SysTick_Handler() noexcept { firmware::tick::on_interrupt(); }
#endif

int main() {
  firmware::install_fault_handler();
  plc.connect(field);
  plc.start();
  // QEMU's MPS2 boards clock the core at 25 MHz: 25,000 cycles are a millisecond. We tick
  // ten times faster than that, 2,500 cycles, so the second of machine time takes a tenth of
  // a second under QEMU; hardware would use its core clock / 1000.
  firmware::tick::start(2500);
  constexpr std::uint32_t run_ms = 1000;
  std::uint32_t done_ms = 0;
  while (done_ms < run_ms) {
    // Catch up with the ticks that came since the last pass, then sleep until the next one.
    while (done_ms < firmware::tick::count() && done_ms < run_ms) {
      field.now_ms = done_ms;
      plc.run_for("T#1ms"_iec);
      ++done_ms;
    }
    if (done_ms < run_ms) firmware::tick::wait();
  }
  const STATS_PRG& stats = plc.get<STATS_PRG>();
  const WORD starts = stats.ctStarts.CV;
  const TIME running = stats.tRunning;
  firmware::print_line("field: star last on at ", field.star_on_ms, " ms, delta last on at ", field.delta_on_ms,
                       " ms, lamp last on at ", field.lamp_on_ms, " ms");
  firmware::print_line("pump: ", field.delta_starts, " starts seen by the field, CTU counted ", starts, ", ran ",
                       running);
  for (DINT i = 1; i <= 3; i = i + 1) print_probe(i);
  for (const task_state& t : plc.tasks()) print_task(t);
  // Each start: the latch at the button's first cycle (20 ms, 700 ms), star for T#50ms, then
  // delta until the cycle that reads STOP (520 ms, 900 ms). Slow samples the motor every 10 ms
  // (after Fast, which has the higher priority): running from 70 to 510 and from 750 to 890 ms.
  // The lamp blinks on every other Blink cycle while the motor is off: last at 600 ms, which
  // the field still sees when Fast writes the outputs at 700 ms, before Blink turns it off.
  const bool ok = field.star_on_ms == 749 && field.delta_on_ms == 899 && field.lamp_on_ms == 700 &&
                  field.delta_starts == 2 && starts == 2 && running == "T#600ms"_iec &&
                  plc.task("Fast").statistics().cycles == 1000 && plc.task("Slow").statistics().cycles == 100 &&
                  plc.task("Blink").statistics().cycles == 10 && probe_saw(1, "Fast", "T#1ms"_iec, 1000U) &&
                  probe_saw(2, "Slow", "T#10ms"_iec, 100U) && probe_saw(3, "Blink", "T#100ms"_iec, 10U) &&
                  GETCURTASKINDEXEX() == 0;  // outside a task cycle
  plc.stop();
  firmware::print_line("RESULT scheduler ", ok ? "PASS" : "FAIL");
  return ok ? firmware::exit_status::passed : firmware::exit_status::failed;
}
