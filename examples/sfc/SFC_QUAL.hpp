// Reference chart SFC_QUAL (its textual SFC in the comments; stimulus and traces in tests/replay/sfc/SFC_QUAL.*), ported line by line: the
// untimed qualifiers N, S, R, P, P1, P0 on a chain INIT -> S1 -> S2 -> S3 -> INIT, each
// transition on NEXT. S1 associates the actions A_N(N), A_S(S), A_P(P), A_P1(P1), A_P0(P0) and
// the BOOL variables V_N(N), V_S(S), V_P(P); S2 none (A_S and V_S stay stored); S3 resets A_S
// and V_S. The scan order is the template argument.
#pragma once

#include <iecoop/iecoop.hpp>

namespace sfc_reference {

using namespace iecoop;

// PROGRAM P_SFC_QUAL
template <sfc::ScanOrder Order = sfc::codesys>
struct P_SFC_QUAL : program<P_SFC_QUAL<Order>> {
  // VAR
  BOOL NEXT;   //   NEXT : BOOL;
  INT C_N;     //   C_N : INT;
  INT C_S;     //   C_S : INT;
  INT C_P;     //   C_P : INT;
  INT C_P1;    //   C_P1 : INT;
  INT C_P0;    //   C_P0 : INT;
  BOOL V_N;    //   V_N : BOOL;
  BOOL V_S;    //   V_S : BOOL;
  BOOL V_P;    //   V_P : BOOL;
  // END_VAR
  sfc::step INIT, S1, S2, S3;

  void A_N() { C_N = C_N + 1; }     // ACTION A_N: C_N := C_N + 1; END_ACTION
  void A_S() { C_S = C_S + 1; }     // ACTION A_S: C_S := C_S + 1; END_ACTION
  void A_P() { C_P = C_P + 1; }     // ACTION A_P: C_P := C_P + 1; END_ACTION
  void A_P1() { C_P1 = C_P1 + 1; }  // ACTION A_P1: C_P1 := C_P1 + 1; END_ACTION
  void A_P0() { C_P0 = C_P0 + 1; }  // ACTION A_P0: C_P0 := C_P0 + 1; END_ACTION

  using P = P_SFC_QUAL;
  sfc::chart<P, Order,
      // INITIAL_STEP INIT: END_STEP
      sfc::INITIAL_STEP<&P::INIT>,
      // TRANSITION FROM INIT TO S1 := NEXT; END_TRANSITION
      sfc::TRANSITION<sfc::FROM<&P::INIT>, sfc::TO<&P::S1>, &P::NEXT>,
      // STEP S1: A_N(N); A_S(S); A_P(P); A_P1(P1); A_P0(P0); V_N(N); V_S(S); V_P(P); END_STEP
      sfc::STEP<&P::S1, sfc::N<&P::A_N>, sfc::S<&P::A_S>, sfc::P<&P::A_P>, sfc::P1<&P::A_P1>, sfc::P0<&P::A_P0>,
                sfc::N<&P::V_N>, sfc::S<&P::V_S>, sfc::P<&P::V_P>>,
      // TRANSITION FROM S1 TO S2 := NEXT; END_TRANSITION
      sfc::TRANSITION<sfc::FROM<&P::S1>, sfc::TO<&P::S2>, &P::NEXT>,
      // STEP S2: END_STEP
      sfc::STEP<&P::S2>,
      // TRANSITION FROM S2 TO S3 := NEXT; END_TRANSITION
      sfc::TRANSITION<sfc::FROM<&P::S2>, sfc::TO<&P::S3>, &P::NEXT>,
      // STEP S3: A_S(R); V_S(R); END_STEP
      sfc::STEP<&P::S3, sfc::R<&P::A_S>, sfc::R<&P::V_S>>,
      // TRANSITION FROM S3 TO INIT := NEXT; END_TRANSITION
      sfc::TRANSITION<sfc::FROM<&P::S3>, sfc::TO<&P::INIT>, &P::NEXT>>
      chart;

  void body() { chart(*this); }
};
// END_PROGRAM

}  // namespace sfc_reference
