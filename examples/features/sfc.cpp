// One feature: a Sequential Function Chart. A tank station waits for START, fills until the
// level switch (a BOOL variable as action: the valve follows the step), heats for 2 s with the
// stirrer stored on (S) until the drain step resets it (R), and drains with a time-limited pump
// (L, 3 s) and counts the batch (P1)
// before it returns to IDLE. The chart runs in a 100 ms task in simulated time, in
// CODESYS's scan order; the program prints every cycle in which a step changes.
#include <fmt/core.h>

#include <iecoop/fmt.hpp>
#include <iecoop/iecoop.hpp>

using namespace iecoop;

// PROGRAM PLC_PRG
struct PLC_PRG : program<PLC_PRG> {
  BOOL START;      // VAR_INPUT START : BOOL;
  BOOL xFull;      //           xFull : BOOL; END_VAR
  BOOL qValve;     // VAR_OUTPUT qValve : BOOL;
  BOOL qHeater;    //            qHeater : BOOL;
  BOOL qStirrer;   //            qStirrer : BOOL;
  BOOL qPump;      //            qPump : BOOL; END_VAR
  UINT uiBatches;  // VAR uiBatches : UINT; END_VAR

  sfc::step IDLE, FILL, HEAT, DRAIN;

  // ACTION A_Heat: qHeater := HEAT.X; END_ACTION
  void A_Heat() { qHeater = HEAT.X; }
  // ACTION A_Count: uiBatches := uiBatches + 1; END_ACTION
  void A_Count() { uiBatches = uiBatches + 1; }
  // TRANSITION T_Heated: HEAT.T >= T#2s          (a named transition object)
  BOOL T_Heated() { return HEAT.T >= "T#2s"_iec; }
  // TRANSITION T_Drained: DRAIN.T >= T#4s
  BOOL T_Drained() { return DRAIN.T >= "T#4s"_iec; }

  using P = PLC_PRG;
  sfc::chart<P,
      // INITIAL_STEP IDLE: END_STEP
      sfc::INITIAL_STEP<&P::IDLE>,
      // TRANSITION FROM IDLE TO FILL := START; END_TRANSITION
      sfc::TRANSITION<sfc::FROM<&P::IDLE>, sfc::TO<&P::FILL>, &P::START>,
      // STEP FILL: qValve(N); END_STEP
      sfc::STEP<&P::FILL, sfc::N<&P::qValve>>,
      // TRANSITION FROM FILL TO HEAT := xFull; END_TRANSITION
      sfc::TRANSITION<sfc::FROM<&P::FILL>, sfc::TO<&P::HEAT>, &P::xFull>,
      // STEP HEAT: A_Heat(N); qStirrer(S); END_STEP
      sfc::STEP<&P::HEAT, sfc::N<&P::A_Heat>, sfc::S<&P::qStirrer>>,
      // TRANSITION FROM HEAT TO DRAIN := T_Heated; END_TRANSITION
      sfc::TRANSITION<sfc::FROM<&P::HEAT>, sfc::TO<&P::DRAIN>, &P::T_Heated>,
      // STEP DRAIN: qStirrer(R); qPump(L, T#3s); A_Count(P1); END_STEP
      sfc::STEP<&P::DRAIN, sfc::R<&P::qStirrer>, sfc::L<&P::qPump, "T#3s">, sfc::P1<&P::A_Count>>,
      // TRANSITION FROM DRAIN TO IDLE := T_Drained; END_TRANSITION
      sfc::TRANSITION<sfc::FROM<&P::DRAIN>, sfc::TO<&P::IDLE>, &P::T_Drained>>
      chart;

  void body() { chart(*this); }
};

int main() {
  PLC_PRG plc_prg;
  fmt::print("time      step   T         valve heater stirrer pump  batches\n");
  STRING<> shown;
  for (int cycle = 0; cycle <= 110; ++cycle) {
    const TIME tNow = "T#100ms"_iec * cycle;
    cycle_clock::set(tNow);                                  // the cycle's time stamp
    plc_prg.START = tNow == "T#500ms"_iec;                   // the operator presses START once
    plc_prg.xFull = tNow >= "T#2s"_iec && tNow < "T#7s"_iec;  // the level switch
    plc_prg();
    const STRING<> step = plc_prg.chart.SFCCurrentStep;
    const bool pump_stops = plc_prg.DRAIN.X && plc_prg.DRAIN.T == "T#3s"_iec;  // L's limit
    if (step != shown || pump_stops) {
      fmt::print("{:<9} {:<6} {:<9} {:<5} {:<6} {:<7} {:<5} {}\n", tNow, step.view(),
                 step == "IDLE" ? TIME(plc_prg.IDLE.T)
                 : step == "FILL" ? TIME(plc_prg.FILL.T)
                 : step == "HEAT" ? TIME(plc_prg.HEAT.T)
                                  : TIME(plc_prg.DRAIN.T),
                 plc_prg.qValve, plc_prg.qHeater, plc_prg.qStirrer, plc_prg.qPump, plc_prg.uiBatches);
      shown = step;
    }
  }
}
