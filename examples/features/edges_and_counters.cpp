// One feature: the edge detectors, bistables and counters of the Standard library, with
// their IEC pins: R_TRIG and F_TRIG, RS (reset wins) and SR (set wins), CTU and CTD.
#include <fmt/core.h>

#include <iecoop/fmt.hpp>
#include <iecoop/iecoop.hpp>

using namespace iecoop;

// PROGRAM PLC_PRG
struct PLC_PRG : program<PLC_PRG> {
  BOOL bButton;  // VAR_INPUT bButton : BOOL;
  BOOL bClear;   //           bClear : BOOL; END_VAR
  R_TRIG rtPressed;  // VAR rtPressed : R_TRIG;
  F_TRIG ftReleased; //     ftReleased : F_TRIG;
  RS rsLatch;        //     rsLatch : RS;
  CTU ctuPresses;    //     ctuPresses : CTU;
  CTD ctdLeft;       //     ctdLeft : CTD; END_VAR

  void body() {
    rtPressed("CLK"_ = bButton);   // rtPressed(CLK := bButton);
    ftReleased("CLK"_ = bButton);  // ftReleased(CLK := bButton);
    rsLatch("S"_ = rtPressed.Q, "R1"_ = bClear);  // rsLatch(S := rtPressed.Q, R1 := bClear);
    // ctuPresses(CU := bButton, RESET := bClear, PV := 3);
    ctuPresses("CU"_ = bButton, "RESET"_ = bClear, "PV"_ = WORD(3));
    // ctdLeft(CD := bButton, LOAD := bClear, PV := 2);
    ctdLeft("CD"_ = bButton, "LOAD"_ = bClear, "PV"_ = WORD(2));
  }
};

int main() {
  PLC_PRG plc_prg;
  // The button is pressed in cycles 1-2, 4 and 6-7; bClear is TRUE in cycles 0 and 9.
  const bool button[] = {false, true, true, false, true, false, true, true, false, false, false};
  fmt::print("cycle button clear | R_TRIG F_TRIG | RS.Q1 | CTU.Q CV | CTD.Q CV\n");
  for (int cycle = 0; cycle < 11; ++cycle) {
    plc_prg.bButton = button[cycle];
    plc_prg.bClear = cycle == 0 || cycle == 9;  // CTD loads PV, CTU resets
    plc_prg();
    fmt::print("{:>5} {:<6} {:<5} | {:<6} {:<6} | {:<5} | {:<5} {:>2} | {:<5} {:>2}\n", cycle, plc_prg.bButton,
               plc_prg.bClear, plc_prg.rtPressed.Q, plc_prg.ftReleased.Q, plc_prg.rsLatch.Q1, plc_prg.ctuPresses.Q,
               plc_prg.ctuPresses.CV, plc_prg.ctdLeft.Q, plc_prg.ctdLeft.CV);
  }
}
