// Reference chart SFC_PAR (its textual SFC in the comments; stimulus and traces in tests/replay/sfc/SFC_PAR.*), ported line by line: a
// simultaneous divergence INIT -> (P1, Q1) on GO; branch P: P1 -> P2 on P1.T >= 30 ms; branch
// Q: Q1 -> Q2 on IN_Q; a simultaneous convergence (P2, Q2) -> JOIN on IN_J, enabled only when
// both P2 and Q2 are active; JOIN -> INIT on JOIN.T >= 20 ms. The scan order is the template
// argument.
#pragma once

#include <iecoop/iecoop.hpp>

namespace sfc_reference {

using namespace iecoop;
using namespace std::chrono_literals;  // T#50ms is 50ms in a condition (see docs/sfc.md, "Transitions")

// PROGRAM P_SFC_PAR
template <sfc::ScanOrder Order = sfc::codesys>
struct P_SFC_PAR : program<P_SFC_PAR<Order>> {
  // VAR
  BOOL GO;      //   GO : BOOL;
  BOOL IN_Q;    //   IN_Q : BOOL;
  BOOL IN_J;    //   IN_J : BOOL;
  INT C_INIT;   //   C_INIT : INT;
  INT C_P1;     //   C_P1 : INT;
  INT C_P2;     //   C_P2 : INT;
  INT C_Q1;     //   C_Q1 : INT;
  INT C_Q2;     //   C_Q2 : INT;
  INT C_JOIN;   //   C_JOIN : INT;
  // END_VAR
  sfc::step INIT, P1, P2, Q1, Q2, JOIN;

  void A_INIT() { C_INIT = C_INIT + 1; }  // ACTION A_INIT: C_INIT := C_INIT + 1; END_ACTION
  void A_P1() { C_P1 = C_P1 + 1; }        // ACTION A_P1: C_P1 := C_P1 + 1; END_ACTION
  void A_P2() { C_P2 = C_P2 + 1; }        // ACTION A_P2: C_P2 := C_P2 + 1; END_ACTION
  void A_Q1() { C_Q1 = C_Q1 + 1; }        // ACTION A_Q1: C_Q1 := C_Q1 + 1; END_ACTION
  void A_Q2() { C_Q2 = C_Q2 + 1; }        // ACTION A_Q2: C_Q2 := C_Q2 + 1; END_ACTION
  void A_JOIN() { C_JOIN = C_JOIN + 1; }  // ACTION A_JOIN: C_JOIN := C_JOIN + 1; END_ACTION

  using P = P_SFC_PAR;
  sfc::chart<P, Order,
      // INITIAL_STEP INIT: A_INIT(N); END_STEP
      sfc::INITIAL_STEP<&P::INIT, sfc::N<&P::A_INIT>>,
      // TRANSITION FROM INIT TO (P1, Q1) := GO; END_TRANSITION
      sfc::TRANSITION<sfc::FROM<&P::INIT>, sfc::TO<&P::P1, &P::Q1>, &P::GO>,
      // STEP P1: A_P1(N); END_STEP
      sfc::STEP<&P::P1, sfc::N<&P::A_P1>>,
      // TRANSITION FROM P1 TO P2 := P1.T >= T#30ms; END_TRANSITION
      sfc::TRANSITION<sfc::FROM<&P::P1>, sfc::TO<&P::P2>, [](auto& p) { return p.P1.T >= 30ms; }>,
      // STEP P2: A_P2(N); END_STEP
      sfc::STEP<&P::P2, sfc::N<&P::A_P2>>,
      // STEP Q1: A_Q1(N); END_STEP
      sfc::STEP<&P::Q1, sfc::N<&P::A_Q1>>,
      // TRANSITION FROM Q1 TO Q2 := IN_Q; END_TRANSITION
      sfc::TRANSITION<sfc::FROM<&P::Q1>, sfc::TO<&P::Q2>, &P::IN_Q>,
      // STEP Q2: A_Q2(N); END_STEP
      sfc::STEP<&P::Q2, sfc::N<&P::A_Q2>>,
      // TRANSITION FROM (P2, Q2) TO JOIN := IN_J; END_TRANSITION
      sfc::TRANSITION<sfc::FROM<&P::P2, &P::Q2>, sfc::TO<&P::JOIN>, &P::IN_J>,
      // STEP JOIN: A_JOIN(N); END_STEP
      sfc::STEP<&P::JOIN, sfc::N<&P::A_JOIN>>,
      // TRANSITION FROM JOIN TO INIT := JOIN.T >= T#20ms; END_TRANSITION
      sfc::TRANSITION<sfc::FROM<&P::JOIN>, sfc::TO<&P::INIT>, [](auto& p) { return p.JOIN.T >= 20ms; }>>
      chart;

  void body() { chart(*this); }
};
// END_PROGRAM

}  // namespace sfc_reference
