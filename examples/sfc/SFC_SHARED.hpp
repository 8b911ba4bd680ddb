// Reference chart SFC_SHARED (its textual SFC in the comments; stimulus and traces in tests/replay/sfc/SFC_SHARED.*), ported line by line: one
// action associated with several steps. A_SH is associated N with S1 and with S2 (the
// associations combine with OR: it runs once per scan); S2 goes back to S1 on BACK (declared
// first) or on to S3 on NEXT AND NOT BACK; A_Q is associated N with S1 and P with S3. The scan
// order is the template argument.
#pragma once

#include <iecoop/iecoop.hpp>

namespace sfc_reference {

using namespace iecoop;

// PROGRAM P_SFC_SHARED
template <sfc::ScanOrder Order = sfc::codesys>
struct P_SFC_SHARED : program<P_SFC_SHARED<Order>> {
  // VAR
  BOOL NEXT;  //   NEXT : BOOL;
  BOOL BACK;  //   BACK : BOOL;
  INT C_SH;   //   C_SH : INT;
  INT C_Q;    //   C_Q : INT;
  // END_VAR
  sfc::step INIT, S1, S2, S3;

  void A_SH() { C_SH = C_SH + 1; }  // ACTION A_SH: C_SH := C_SH + 1; END_ACTION
  void A_Q() { C_Q = C_Q + 1; }     // ACTION A_Q: C_Q := C_Q + 1; END_ACTION

  using P = P_SFC_SHARED;
  sfc::chart<P, Order,
      // INITIAL_STEP INIT: END_STEP
      sfc::INITIAL_STEP<&P::INIT>,
      // TRANSITION FROM INIT TO S1 := NEXT; END_TRANSITION
      sfc::TRANSITION<sfc::FROM<&P::INIT>, sfc::TO<&P::S1>, &P::NEXT>,
      // STEP S1: A_SH(N); A_Q(N); END_STEP
      sfc::STEP<&P::S1, sfc::N<&P::A_SH>, sfc::N<&P::A_Q>>,
      // TRANSITION FROM S1 TO S2 := NEXT; END_TRANSITION
      sfc::TRANSITION<sfc::FROM<&P::S1>, sfc::TO<&P::S2>, &P::NEXT>,
      // STEP S2: A_SH(N); END_STEP
      sfc::STEP<&P::S2, sfc::N<&P::A_SH>>,
      // TRANSITION FROM S2 TO S1 := BACK; END_TRANSITION
      sfc::TRANSITION<sfc::FROM<&P::S2>, sfc::TO<&P::S1>, &P::BACK>,
      // TRANSITION FROM S2 TO S3 := NEXT AND NOT BACK; END_TRANSITION
      sfc::TRANSITION<sfc::FROM<&P::S2>, sfc::TO<&P::S3>, [](auto& p) { return p.NEXT && !p.BACK; }>,
      // STEP S3: A_Q(P); END_STEP
      sfc::STEP<&P::S3, sfc::P<&P::A_Q>>,
      // TRANSITION FROM S3 TO INIT := NEXT; END_TRANSITION
      sfc::TRANSITION<sfc::FROM<&P::S3>, sfc::TO<&P::INIT>, &P::NEXT>>
      chart;

  void body() { chart(*this); }
};
// END_PROGRAM

}  // namespace sfc_reference
