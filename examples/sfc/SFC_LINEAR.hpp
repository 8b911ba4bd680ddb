// Reference chart SFC_LINEAR (its textual SFC in the comments; stimulus and traces in tests/replay/sfc/SFC_LINEAR.*), ported line by line: a
// linear sequence INIT -> FILL -> PULSE -> HEAT -> CNT -> back to INIT. FILL leaves on FILL.T >=
// 50 ms; PULSE leaves unconditionally (active for one scan); HEAT on HEAT.T > 25 ms AND NOT
// START; CNT clears K with a P action, increments it with an N action and leaves on K >= 3 (a
// transition that reads a variable an action writes). The counters show in which scans each
// action body runs. The scan order is the template argument (sfc::codesys unless given).
#pragma once

#include <iecoop/iecoop.hpp>

namespace sfc_reference {

using namespace iecoop;
using namespace std::chrono_literals;  // T#50ms is 50ms in a condition (see docs/sfc.md, "Transitions")

// PROGRAM P_SFC_LINEAR
template <sfc::ScanOrder Order = sfc::codesys>
struct P_SFC_LINEAR : program<P_SFC_LINEAR<Order>> {
  // VAR
  BOOL START;         //   START : BOOL;
  INT C_INIT;         //   C_INIT : INT;
  INT C_FILL;         //   C_FILL : INT;
  INT C_PULSE;        //   C_PULSE : INT;
  INT C_HEAT;         //   C_HEAT : INT;
  TIME FILL_T_SEEN;   //   FILL_T_SEEN : TIME;
  INT K;              //   K : INT;
  // END_VAR

  sfc::step INIT, FILL, PULSE, HEAT, CNT;  // the steps' implicit variables (INIT.X, FILL.T, ...)

  void A_INIT() { C_INIT = C_INIT + 1; }  // ACTION A_INIT: C_INIT := C_INIT + 1; END_ACTION
  void A_FILL() {                         // ACTION A_FILL:
    C_FILL = C_FILL + 1;                  //   C_FILL := C_FILL + 1;
    FILL_T_SEEN = FILL.T;                 //   FILL_T_SEEN := FILL.T;
  }                                       // END_ACTION
  void A_PULSE() { C_PULSE = C_PULSE + 1; }  // ACTION A_PULSE: C_PULSE := C_PULSE + 1; END_ACTION
  void A_HEAT() { C_HEAT = C_HEAT + 1; }     // ACTION A_HEAT: C_HEAT := C_HEAT + 1; END_ACTION
  void A_K_CLEAR() { K = 0; }                // ACTION A_K_CLEAR: K := 0; END_ACTION
  void A_K_INC() { K = K + 1; }              // ACTION A_K_INC: K := K + 1; END_ACTION

  using P = P_SFC_LINEAR;
  sfc::chart<P, Order,
      // INITIAL_STEP INIT: A_INIT(N); END_STEP
      sfc::INITIAL_STEP<&P::INIT, sfc::N<&P::A_INIT>>,
      // TRANSITION FROM INIT TO FILL := START; END_TRANSITION
      sfc::TRANSITION<sfc::FROM<&P::INIT>, sfc::TO<&P::FILL>, &P::START>,
      // STEP FILL: A_FILL(N); END_STEP
      sfc::STEP<&P::FILL, sfc::N<&P::A_FILL>>,
      // TRANSITION FROM FILL TO PULSE := FILL.T >= T#50ms; END_TRANSITION
      sfc::TRANSITION<sfc::FROM<&P::FILL>, sfc::TO<&P::PULSE>, [](auto& p) { return p.FILL.T >= 50ms; }>,
      // STEP PULSE: A_PULSE(N); END_STEP
      sfc::STEP<&P::PULSE, sfc::N<&P::A_PULSE>>,
      // TRANSITION FROM PULSE TO HEAT := TRUE; END_TRANSITION
      sfc::TRANSITION<sfc::FROM<&P::PULSE>, sfc::TO<&P::HEAT>, true>,
      // STEP HEAT: A_HEAT(N); END_STEP
      sfc::STEP<&P::HEAT, sfc::N<&P::A_HEAT>>,
      // TRANSITION FROM HEAT TO CNT := HEAT.T > T#25ms AND NOT START; END_TRANSITION
      sfc::TRANSITION<sfc::FROM<&P::HEAT>, sfc::TO<&P::CNT>,
                      [](auto& p) { return (p.HEAT.T > 25ms && !p.START); }>,
      // STEP CNT: A_K_CLEAR(P); A_K_INC(N); END_STEP
      sfc::STEP<&P::CNT, sfc::P<&P::A_K_CLEAR>, sfc::N<&P::A_K_INC>>,
      // TRANSITION FROM CNT TO INIT := K >= 3; END_TRANSITION
      sfc::TRANSITION<sfc::FROM<&P::CNT>, sfc::TO<&P::INIT>, [](auto& p) { return p.K >= 3; }>>
      chart;

  void body() { chart(*this); }
};
// END_PROGRAM

}  // namespace sfc_reference
