// Reference chart SFC_FIRST_SCAN (its textual SFC in the comments; stimulus and traces in tests/replay/sfc/SFC_FIRST_SCAN.*), ported line by
// line: INIT (initial, with an N, a P and a P0 action) and S1; INIT -> S1 on GO, S1 -> INIT on
// BACK, and a self-loop INIT -> INIT on AGAIN (declared after GO). Replayed with GO TRUE on the
// very first scan (SFC_FIRST_SCAN.stimulus.csv) and with GO FALSE then
// (SFC_FIRST_SCAN_init_low.stimulus.csv). The scan order is the template argument.
#pragma once

#include <iecoop/iecoop.hpp>

namespace sfc_reference {

using namespace iecoop;

// PROGRAM P_SFC_FIRST_SCAN
template <sfc::ScanOrder Order = sfc::codesys>
struct P_SFC_FIRST_SCAN : program<P_SFC_FIRST_SCAN<Order>> {
  // VAR
  BOOL GO;         //   GO : BOOL;
  BOOL BACK;       //   BACK : BOOL;
  BOOL AGAIN;      //   AGAIN : BOOL;
  INT C_INIT_N;    //   C_INIT_N : INT;
  INT C_INIT_P;    //   C_INIT_P : INT;
  INT C_INIT_P0;   //   C_INIT_P0 : INT;
  INT C_S1;        //   C_S1 : INT;
  // END_VAR
  sfc::step INIT, S1;

  void A_INIT_N() { C_INIT_N = C_INIT_N + 1; }     // ACTION A_INIT_N: C_INIT_N := C_INIT_N + 1; END_ACTION
  void A_INIT_P() { C_INIT_P = C_INIT_P + 1; }     // ACTION A_INIT_P: C_INIT_P := C_INIT_P + 1; END_ACTION
  void A_INIT_P0() { C_INIT_P0 = C_INIT_P0 + 1; }  // ACTION A_INIT_P0: C_INIT_P0 := C_INIT_P0 + 1; END_ACTION
  void A_S1() { C_S1 = C_S1 + 1; }                 // ACTION A_S1: C_S1 := C_S1 + 1; END_ACTION

  using P = P_SFC_FIRST_SCAN;
  sfc::chart<P, Order,
      // INITIAL_STEP INIT: A_INIT_N(N); A_INIT_P(P); A_INIT_P0(P0); END_STEP
      sfc::INITIAL_STEP<&P::INIT, sfc::N<&P::A_INIT_N>, sfc::P<&P::A_INIT_P>, sfc::P0<&P::A_INIT_P0>>,
      // TRANSITION FROM INIT TO S1 := GO; END_TRANSITION
      sfc::TRANSITION<sfc::FROM<&P::INIT>, sfc::TO<&P::S1>, &P::GO>,
      // TRANSITION FROM INIT TO INIT := AGAIN; END_TRANSITION
      sfc::TRANSITION<sfc::FROM<&P::INIT>, sfc::TO<&P::INIT>, &P::AGAIN>,
      // STEP S1: A_S1(N); END_STEP
      sfc::STEP<&P::S1, sfc::N<&P::A_S1>>,
      // TRANSITION FROM S1 TO INIT := BACK; END_TRANSITION
      sfc::TRANSITION<sfc::FROM<&P::S1>, sfc::TO<&P::INIT>, &P::BACK>>
      chart;

  void body() { chart(*this); }
};
// END_PROGRAM

}  // namespace sfc_reference
