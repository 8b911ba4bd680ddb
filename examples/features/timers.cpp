// One feature: the standard timers TON, TOF and TP in simulated time. Each reads the time
// stamp of its task's cycle; here a loop sets it every 100 ms, as a 100 ms task would, and a
// whole second of machine time runs in microseconds.
#include <fmt/core.h>

#include <iecoop/fmt.hpp>
#include <iecoop/iecoop.hpp>

using namespace iecoop;

// PROGRAM PLC_PRG
struct PLC_PRG : program<PLC_PRG> {
  BOOL bSwitch;   // VAR_INPUT bSwitch : BOOL; END_VAR
  TON tOnDelay;   // VAR tOnDelay : TON;
  TOF tOffDelay;  //     tOffDelay : TOF;
  TP tPulse;      //     tPulse : TP; END_VAR

  void body() {
    tOnDelay("IN"_ = bSwitch, "PT"_ = "T#300ms"_iec);   // tOnDelay(IN := bSwitch, PT := T#300ms);
    tOffDelay("IN"_ = bSwitch, "PT"_ = "T#200ms"_iec);  // tOffDelay(IN := bSwitch, PT := T#200ms);
    tPulse("IN"_ = bSwitch, "PT"_ = "T#250ms"_iec);     // tPulse(IN := bSwitch, PT := T#250ms);
  }
};

int main() {
  PLC_PRG plc_prg;
  fmt::print("time      IN     | TON PT=300ms       | TOF PT=200ms       | TP PT=250ms\n");
  TIME tNow = "T#0ms"_iec;
  for (int cycle = 0; cycle <= 12; ++cycle) {
    cycle_clock::set(tNow);                                    // the cycle's time stamp
    plc_prg.bSwitch = tNow >= "T#100ms"_iec && tNow < "T#700ms"_iec;  // on from 0.1 s to 0.7 s
    plc_prg();
    fmt::print("{:<9} {:<6} | Q {:<5} ET {:<8} | Q {:<5} ET {:<8} | Q {:<5} ET {}\n", tNow, plc_prg.bSwitch,
               plc_prg.tOnDelay.Q, plc_prg.tOnDelay.ET, plc_prg.tOffDelay.Q, plc_prg.tOffDelay.ET, plc_prg.tPulse.Q,
               plc_prg.tPulse.ET);
    tNow = tNow + "T#100ms"_iec;
  }
}
