// Firmware example: a trace recorder on the target. A conveyor is started and stopped by push
// buttons (RS), a CTU counts the parts at its photo eye, and a TON detects a jam; the trace
// records the I/O, the TON's pins and the count after every cycle of the task, triggers on the
// jam, keeps the samples before it, and is dumped at the end through semihosting as a VCD file
// (for GTKWave) and as CSV.
//
//   Task    Main   cyclic T#10ms   priority 1   CONVEYOR_PRG
//
//   CODESYS Trace configuration              iecoop
//     Task: Main                               trace.attach(plc.task("Main"));
//     Variables: the I/O of CONVEYOR_PRG,      trace.add_located(...); trace.add(...);
//       bJam, tJam's pins, ctParts.CV            trace.add_pins(...); trace.add(...);
//     Trigger variable: CONVEYOR_PRG.bJam      trace.trigger_on(prg.bJam, trace_edge::rising,
//     Trigger edge: positive                                    /*pre_trigger=*/5,
//     Post trigger (samples): 12                                /*post_trigger=*/12);
//     Record condition: every cycle            (the default: trace_mode::every_cycle)
//
// The field is simulated by the I/O driver: an operator presses START at 20 ms; parts pass
// the photo eye at 100, 160 and 220 ms (two cycles each); the fourth, at 280 ms, sticks, and
// 50 ms later the TON reports the jam, which stops the belt. The operator clears the part at
// 400 ms and presses START again at 430 ms; one more part passes at 480 ms. After 500 ms of
// machine time (50 cycles) main() writes the trace: 5 samples before the jam (280 .. 320 ms),
// the jam at 330 ms and 12 after it (340 .. 450 ms).
//
// The recorder is a static object with 2 KiB of sample memory (23 bytes a sample here); the
// writers put the text through a callable piece by piece, with no buffer beyond one number's
// text, so the dump needs neither heap nor stdio. Its channels point into the application's
// program instance, which exists from plc.start() to plc.stop(): they are added after the
// one, and the trace is written before the other.
#include <cstdint>
#include <span>
#include <string_view>

#include <iecoop/iecoop.hpp>
#include <iecoop/trace.hpp>

#include "console.hpp"
#include "exit_status.hpp"
#include "fault_handler.hpp"

namespace {

using namespace iecoop;

// The process image: %IB0 and %QB0 only.
struct conveyor_image_tag {};
using conveyor_image = process_image<1, 1, 0, addressing::codesys, conveyor_image_tag>;

// PROGRAM CONVEYOR_PRG
struct CONVEYOR_PRG : program<CONVEYOR_PRG> {
  // VAR
  [[no_unique_address]] located<BOOL, "%IX0.0", conveyor_image> ixStart;  // ixStart AT %IX0.0 : BOOL;
  [[no_unique_address]] located<BOOL, "%IX0.1", conveyor_image> ixStop;   // ixStop AT %IX0.1 : BOOL;
  [[no_unique_address]] located<BOOL, "%IX0.2", conveyor_image> ixEye;    // ixEye AT %IX0.2 : BOOL;
  [[no_unique_address]] located<BOOL, "%QX0.0", conveyor_image> qxMotor;  // qxMotor AT %QX0.0 : BOOL;
  [[no_unique_address]] located<BOOL, "%QX0.1", conveyor_image> qxJam;    // qxJam AT %QX0.1 : BOOL;
  RS rsMotor;                                                             // rsMotor : RS;
  TON tJam;                                                               // tJam : TON;
  CTU ctParts;                                                            // ctParts : CTU;
  BOOL bJam;                                                              // bJam : BOOL;
  // END_VAR
  using LOCATED = pins<&CONVEYOR_PRG::ixStart, &CONVEYOR_PRG::ixStop, &CONVEYOR_PRG::ixEye, &CONVEYOR_PRG::qxMotor,
                       &CONVEYOR_PRG::qxJam>;

  void body() {
    // A part that blocks the eye for T#50ms while the belt runs is stuck.
    tJam("IN"_ = ixEye && rsMotor.Q1, "PT"_ = "T#50ms"_iec);      // tJam(IN := ixEye AND rsMotor.Q1, PT := T#50ms);
    bJam = (bJam || tJam.Q) && !ixStart;                          // bJam := (bJam OR tJam.Q) AND NOT ixStart;
    rsMotor("S"_ = ixStart, "R1"_ = ixStop || bJam);              // rsMotor(S := ixStart, R1 := ixStop OR bJam);
    ctParts("CU"_ = ixEye, "RESET"_ = FALSE, "PV"_ = WORD(100));  // ctParts(CU := ixEye, PV := 100);
    qxMotor = rsMotor.Q1;                                         // qxMotor := rsMotor.Q1;
    qxJam = bJam;                                                 // qxJam := bJam;
  }
};

// The simulated field: the operator's buttons and the photo eye on %IB0.
struct conveyor_field {
  std::uint32_t now_ms = 0;  // set by the main loop before each cycle runs
  std::byte outputs{};

  void read_inputs(std::span<std::byte> inputs) const {
    const auto between = [this](std::uint32_t from, std::uint32_t to) { return now_ms >= from && now_ms < to; };
    const bool start = between(20, 40) || between(430, 450);
    const bool eye =
        between(100, 120) || between(160, 180) || between(220, 240) || between(280, 400) || between(480, 500);
    inputs[0] = std::byte((start ? 0x01U : 0U) | (eye ? 0x04U : 0U));
  }
  void write_outputs(std::span<const std::byte> out) { outputs = out[0]; }
};

// TASK Main (INTERVAL := T#10ms, PRIORITY := 1);   PROGRAM Conveyor WITH Main : CONVEYOR_PRG;
application plc{
    task<CONVEYOR_PRG>{"Main", cyclic{"T#10ms"_iec}, 1},
    use_image<conveyor_image>{},
    retain_capacity<0>{},
};
conveyor_field field;
// 2 KiB of samples, up to 16 channels.
trace_recorder<2048, 16> trace;

// The writers' output: each piece of text goes straight to the console (semihosting).
void put_text(std::string_view text) { firmware::put(text); }

}  // namespace

int main() {
  firmware::install_fault_handler();
  plc.connect(field);
  plc.start();  // constructs the program instance: the channels name its variables
  CONVEYOR_PRG& prg = plc.get<CONVEYOR_PRG>();
  trace.add_located("CONVEYOR_PRG", prg);  // the I/O: ixStart, ixStop, ixEye, qxMotor, qxJam
  trace.add("CONVEYOR_PRG", "bJam", prg.bJam);
  trace.add_pins("CONVEYOR_PRG.tJam", prg.tJam);  // IN, PT, Q, ET
  trace.add("CONVEYOR_PRG.ctParts", "CV", prg.ctParts.CV);
  trace.trigger_on(prg.bJam, trace_edge::rising, 5, 12);
  trace.attach(plc.task("Main"));
  trace.start();
  for (std::uint32_t t = 0; t < 500; t += 10) {
    field.now_ms = t;
    plc.run_for("T#10ms"_iec);
  }

  const trace_view view = trace.view();
  const std::size_t at = view.trigger_index();
  const WORD parts = prg.ctParts.CV;
  const BOOL motor = prg.qxMotor;
  firmware::print_line("conveyor: ", parts, " parts counted, motor ", motor);
  firmware::print_line("trace: ", trace.channel_count(), " channels, ", trace.sample_bytes(), " bytes a sample, ",
                       trace.capacity(), " samples fit; ", to_string(trace.state()), " with ", view.size(),
                       " samples, the trigger at sample ", at, " (cycle ", view.cycle(at), ")");
  firmware::print_line("--- begin trace.vcd");
  write_vcd(view, put_text);
  firmware::print_line("--- end trace.vcd");
  firmware::print_line("--- begin trace.csv");
  write_csv(view, put_text);
  firmware::print_line("--- end trace.csv");

  // The jam: the part sticks at 280 ms, the TON's Q rises 50 ms later (cycle 33), and the
  // trace keeps cycles 28 .. 45.
  const bool ok = trace.complete() && view.size() == 18 && at == 5 && view.cycle(at) == 33 &&
                  view.time(at) == LTIME("T#330ms"_iec) && view.cycle(0) == 28 && parts == 5 && motor;
  plc.stop();  // ends the instances: the trace's channels must not be read after this
  firmware::print_line("RESULT trace ", ok ? "PASS" : "FAIL");
  return ok ? firmware::exit_status::passed : firmware::exit_status::failed;
}
