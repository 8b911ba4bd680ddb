// Reference charts SFC_ALT and SFC_ALT_PRIO (their textual SFC in the comments; stimuli and
// traces in tests/replay/sfc/SFC_ALT.* and SFC_ALT_PRIO.*), ported line by line: an alternative divergence INIT -> BR_A | BR_B, the two
// branches converging on JOIN, and a jump from BR_B back to INIT on ABORT. SFC_ALT gives no
// priorities: the transition declared first (the left-most branch) wins. SFC_ALT_PRIO gives
// INIT -> BR_B and BR_B -> JOIN priority 1. The scan order is the template argument.
#pragma once

#include <iecoop/iecoop.hpp>

namespace sfc_reference {

using namespace iecoop;

// The variables and actions both charts share.
struct alt_variables {
  // VAR
  BOOL GO_A;    //   GO_A : BOOL;
  BOOL GO_B;    //   GO_B : BOOL;
  BOOL DONE;    //   DONE : BOOL;
  BOOL ABORT;   //   ABORT : BOOL;
  INT C_INIT;   //   C_INIT : INT;
  INT C_A;      //   C_A : INT;
  INT C_B;      //   C_B : INT;
  INT C_JOIN;   //   C_JOIN : INT;
  // END_VAR
  sfc::step INIT, BR_A, BR_B, JOIN;

  void A_INIT() { C_INIT = C_INIT + 1; }  // ACTION A_INIT: C_INIT := C_INIT + 1; END_ACTION
  void A_A() { C_A = C_A + 1; }           // ACTION A_A: C_A := C_A + 1; END_ACTION
  void A_B() { C_B = C_B + 1; }           // ACTION A_B: C_B := C_B + 1; END_ACTION
  void A_JOIN() { C_JOIN = C_JOIN + 1; }  // ACTION A_JOIN: C_JOIN := C_JOIN + 1; END_ACTION
};

// PROGRAM P_SFC_ALT
template <sfc::ScanOrder Order = sfc::codesys>
struct P_SFC_ALT : program<P_SFC_ALT<Order>>, alt_variables {
  using P = P_SFC_ALT;
  sfc::chart<P, Order,
      // INITIAL_STEP INIT: A_INIT(N); END_STEP
      sfc::INITIAL_STEP<&P::INIT, sfc::N<&P::A_INIT>>,
      // TRANSITION FROM INIT TO BR_A := GO_A; END_TRANSITION
      sfc::TRANSITION<sfc::FROM<&P::INIT>, sfc::TO<&P::BR_A>, &P::GO_A>,
      // TRANSITION FROM INIT TO BR_B := GO_B; END_TRANSITION
      sfc::TRANSITION<sfc::FROM<&P::INIT>, sfc::TO<&P::BR_B>, &P::GO_B>,
      // STEP BR_A: A_A(N); END_STEP
      sfc::STEP<&P::BR_A, sfc::N<&P::A_A>>,
      // STEP BR_B: A_B(N); END_STEP
      sfc::STEP<&P::BR_B, sfc::N<&P::A_B>>,
      // TRANSITION FROM BR_A TO JOIN := DONE; END_TRANSITION
      sfc::TRANSITION<sfc::FROM<&P::BR_A>, sfc::TO<&P::JOIN>, &P::DONE>,
      // TRANSITION FROM BR_B TO JOIN := DONE; END_TRANSITION
      sfc::TRANSITION<sfc::FROM<&P::BR_B>, sfc::TO<&P::JOIN>, &P::DONE>,
      // TRANSITION FROM BR_B TO INIT := ABORT; END_TRANSITION
      sfc::TRANSITION<sfc::FROM<&P::BR_B>, sfc::TO<&P::INIT>, &P::ABORT>,
      // STEP JOIN: A_JOIN(N); END_STEP
      sfc::STEP<&P::JOIN, sfc::N<&P::A_JOIN>>,
      // TRANSITION FROM JOIN TO INIT := TRUE; END_TRANSITION
      sfc::TRANSITION<sfc::FROM<&P::JOIN>, sfc::TO<&P::INIT>, true>>
      chart;

  void body() { chart(*this); }
};
// END_PROGRAM

// PROGRAM P_SFC_ALT_PRIO
template <sfc::ScanOrder Order = sfc::codesys>
struct P_SFC_ALT_PRIO : program<P_SFC_ALT_PRIO<Order>>, alt_variables {
  using P = P_SFC_ALT_PRIO;
  sfc::chart<P, Order,
      // INITIAL_STEP INIT: A_INIT(N); END_STEP
      sfc::INITIAL_STEP<&P::INIT, sfc::N<&P::A_INIT>>,
      // TRANSITION (PRIORITY := 2) FROM INIT TO BR_A := GO_A; END_TRANSITION
      sfc::TRANSITION<sfc::FROM<&P::INIT>, sfc::TO<&P::BR_A>, &P::GO_A, sfc::PRIORITY<2>>,
      // TRANSITION (PRIORITY := 1) FROM INIT TO BR_B := GO_B; END_TRANSITION
      sfc::TRANSITION<sfc::FROM<&P::INIT>, sfc::TO<&P::BR_B>, &P::GO_B, sfc::PRIORITY<1>>,
      // STEP BR_A: A_A(N); END_STEP
      sfc::STEP<&P::BR_A, sfc::N<&P::A_A>>,
      // STEP BR_B: A_B(N); END_STEP
      sfc::STEP<&P::BR_B, sfc::N<&P::A_B>>,
      // TRANSITION FROM BR_A TO JOIN := DONE; END_TRANSITION
      sfc::TRANSITION<sfc::FROM<&P::BR_A>, sfc::TO<&P::JOIN>, &P::DONE>,
      // TRANSITION (PRIORITY := 1) FROM BR_B TO JOIN := DONE; END_TRANSITION
      sfc::TRANSITION<sfc::FROM<&P::BR_B>, sfc::TO<&P::JOIN>, &P::DONE, sfc::PRIORITY<1>>,
      // TRANSITION (PRIORITY := 2) FROM BR_B TO INIT := ABORT; END_TRANSITION
      sfc::TRANSITION<sfc::FROM<&P::BR_B>, sfc::TO<&P::INIT>, &P::ABORT, sfc::PRIORITY<2>>,
      // STEP JOIN: A_JOIN(N); END_STEP
      sfc::STEP<&P::JOIN, sfc::N<&P::A_JOIN>>,
      // TRANSITION FROM JOIN TO INIT := TRUE; END_TRANSITION
      sfc::TRANSITION<sfc::FROM<&P::JOIN>, sfc::TO<&P::INIT>, true>>
      chart;

  void body() { chart(*this); }
};
// END_PROGRAM

}  // namespace sfc_reference
