// Firmware example: the standard timers (TON, TOF, TP) and counters (CTU, CTD, CTUD) in a
// PROGRAM called every 10 ms, with the cycle clock set before each call as a task would.
//
// A switch (bSwitch) is on from 100 ms to 800 ms; a 40 ms clock (bClock) toggles every
// 20 ms. The timers watch the switch, the counters count the clock's rising edges. The
// program records when each output changes; main() checks the instants against the
// standard's definitions.
#include <iecoop/iecoop.hpp>

#include "console.hpp"
#include "exit_status.hpp"
#include "fault_handler.hpp"
#include "scan_cost.hpp"

namespace {

using namespace iecoop;

// PROGRAM PLC_PRG
struct PLC_PRG : program<PLC_PRG> {
  // VAR_INPUT
  BOOL bSwitch;  // bSwitch : BOOL;
  BOOL bClock;   // bClock : BOOL;
  // END_VAR
  // VAR
  TON tOnDelay;   // tOnDelay : TON;
  TOF tOffDelay;  // tOffDelay : TOF;
  TP tPulse;      // tPulse : TP;
  CTU ctUp;       // ctUp : CTU;
  CTD ctDown;     // ctDown : CTD;
  CTUD ctUpDown;  // ctUpDown : CTUD;
  // END_VAR

  void body() {
    tOnDelay("IN"_ = bSwitch, "PT"_ = "T#300ms"_iec);   // tOnDelay(IN := bSwitch, PT := T#300ms);
    tOffDelay("IN"_ = bSwitch, "PT"_ = "T#200ms"_iec);  // tOffDelay(IN := bSwitch, PT := T#200ms);
    tPulse("IN"_ = bSwitch, "PT"_ = "T#250ms"_iec);     // tPulse(IN := bSwitch, PT := T#250ms);
    // ctUp(CU := bClock, RESET := NOT bSwitch, PV := 10);     counts while the switch is on
    ctUp("CU"_ = bClock, "RESET"_ = !bSwitch, "PV"_ = WORD(10));
    // ctDown(CD := bClock, LOAD := NOT bSwitch, PV := 5);     counts 5 down to 0 while it is on
    ctDown("CD"_ = bClock, "LOAD"_ = !bSwitch, "PV"_ = WORD(5));
    // ctUpDown(CU := bClock AND bSwitch, CD := bClock AND NOT bSwitch, PV := 12);
    ctUpDown("CU"_ = bClock & bSwitch, "CD"_ = bClock & !bSwitch, "PV"_ = WORD(12));
  }
};

PLC_PRG plc_prg;

// When an output changed last, in ms since the start (-1: never).
struct edge_times {
  long rose = -1;
  long fell = -1;
  void record(BOOL before, BOOL now, long at) {
    if (now && !before) rose = at;
    if (!now && before) fell = at;
  }
};

}  // namespace

int main() {
  firmware::install_fault_handler();
  firmware::scan_cost::start();  // only a build with IECOOP_FIRMWARE_SCAN_COST measures (scan_cost.hpp)
  edge_times on_delay, off_delay, pulse, up, down, up_down_q;
  for (long t = 0; t <= 1500; t += 10) {
    const BOOL on_before = plc_prg.tOnDelay.Q, off_before = plc_prg.tOffDelay.Q, pulse_before = plc_prg.tPulse.Q;
    const BOOL up_before = plc_prg.ctUp.Q, down_before = plc_prg.ctDown.Q, up_down_before = plc_prg.ctUpDown.QU;
    // The cycle: the time stamp of its start, the inputs, the program.
    cycle_clock::set(LTIME::from_ticks(static_cast<std::uint64_t>(t) * 1000000U));  // ms in ns
    plc_prg.bSwitch = t >= 100 && t < 800;
    plc_prg.bClock = (t / 20) % 2 == 1;
    firmware::scan_cost::begin();
    plc_prg();
    firmware::scan_cost::end();
    on_delay.record(on_before, plc_prg.tOnDelay.Q, t);
    off_delay.record(off_before, plc_prg.tOffDelay.Q, t);
    pulse.record(pulse_before, plc_prg.tPulse.Q, t);
    up.record(up_before, plc_prg.ctUp.Q, t);
    down.record(down_before, plc_prg.ctDown.Q, t);
    up_down_q.record(up_down_before, plc_prg.ctUpDown.QU, t);
  }
  const WORD up_down_cv = plc_prg.ctUpDown.CV;
  firmware::print_line("TON  PT=300ms: Q rose at ", on_delay.rose, " ms, fell at ", on_delay.fell, " ms");
  firmware::print_line("TOF  PT=200ms: Q rose at ", off_delay.rose, " ms, fell at ", off_delay.fell, " ms");
  firmware::print_line("TP   PT=250ms: Q rose at ", pulse.rose, " ms, fell at ", pulse.fell, " ms");
  firmware::print_line("CTU  PV=10: Q rose at ", up.rose, " ms, fell at ", up.fell, " ms");
  firmware::print_line("CTD  PV=5: Q rose at ", down.rose, " ms, fell at ", down.fell, " ms");
  firmware::print_line("CTUD PV=12: QU rose at ", up_down_q.rose, " ms, CV = ", up_down_cv, " at the end");
  // The switch is on from 100 ms to 800 ms; the clock rises at 20 ms, 60 ms, 100 ms, ...
  const bool ok = on_delay.rose == 400 && on_delay.fell == 800        // 300 ms after the switch; with it
                  && off_delay.rose == 100 && off_delay.fell == 1000  // with the switch; 200 ms after
                  && pulse.rose == 100 && pulse.fell == 350           // 250 ms from the switch's edge
                  && up.rose == 460 && up.fell == 800                 // 10th edge after 100 ms; RESET
                  && down.rose == 260 && down.fell == 800             // 5 edges from 5 to 0; LOAD
                  && up_down_q.rose == 540 && up_down_cv == 0;        // 12th edge up; then counted down
  firmware::scan_cost::report("timers_counters");
  firmware::print_line("RESULT timers_counters ", ok ? "PASS" : "FAIL");
  return ok ? firmware::exit_status::passed : firmware::exit_status::failed;
}
