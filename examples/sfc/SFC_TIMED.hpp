// Reference chart SFC_TIMED (its textual SFC in the comments; stimulus and traces in tests/replay/sfc/SFC_TIMED.*), ported line by line: the
// timed qualifiers L, D, SD, DS, SL, all with T#30ms, on a chain INIT -> S1 -> S2 -> S3 -> S4 ->
// INIT, each transition on NEXT. S1: A_L(L), A_D(D) and the BOOL variables V_L(L), V_D(D); S2:
// A_SD(SD), A_DS(DS), A_SL(SL); S3: nothing (waits between S2 and the resets); S4 resets A_SD,
// A_DS and A_SL. The scan order is the template argument.
#pragma once

#include <iecoop/iecoop.hpp>

namespace sfc_reference {

using namespace iecoop;

// PROGRAM P_SFC_TIMED
template <sfc::ScanOrder Order = sfc::codesys>
struct P_SFC_TIMED : program<P_SFC_TIMED<Order>> {
  // VAR
  BOOL NEXT;   //   NEXT : BOOL;
  INT C_L;     //   C_L : INT;
  INT C_D;     //   C_D : INT;
  INT C_SD;    //   C_SD : INT;
  INT C_DS;    //   C_DS : INT;
  INT C_SL;    //   C_SL : INT;
  BOOL V_L;    //   V_L : BOOL;
  BOOL V_D;    //   V_D : BOOL;
  // END_VAR
  sfc::step INIT, S1, S2, S3, S4;

  void A_L() { C_L = C_L + 1; }     // ACTION A_L: C_L := C_L + 1; END_ACTION
  void A_D() { C_D = C_D + 1; }     // ACTION A_D: C_D := C_D + 1; END_ACTION
  void A_SD() { C_SD = C_SD + 1; }  // ACTION A_SD: C_SD := C_SD + 1; END_ACTION
  void A_DS() { C_DS = C_DS + 1; }  // ACTION A_DS: C_DS := C_DS + 1; END_ACTION
  void A_SL() { C_SL = C_SL + 1; }  // ACTION A_SL: C_SL := C_SL + 1; END_ACTION

  using P = P_SFC_TIMED;
  sfc::chart<P, Order,
      // INITIAL_STEP INIT: END_STEP
      sfc::INITIAL_STEP<&P::INIT>,
      // TRANSITION FROM INIT TO S1 := NEXT; END_TRANSITION
      sfc::TRANSITION<sfc::FROM<&P::INIT>, sfc::TO<&P::S1>, &P::NEXT>,
      // STEP S1: A_L(L, T#30ms); A_D(D, T#30ms); V_L(L, T#30ms); V_D(D, T#30ms); END_STEP
      sfc::STEP<&P::S1, sfc::L<&P::A_L, "T#30ms">, sfc::D<&P::A_D, "T#30ms">, sfc::L<&P::V_L, "T#30ms">,
                sfc::D<&P::V_D, "T#30ms">>,
      // TRANSITION FROM S1 TO S2 := NEXT; END_TRANSITION
      sfc::TRANSITION<sfc::FROM<&P::S1>, sfc::TO<&P::S2>, &P::NEXT>,
      // STEP S2: A_SD(SD, T#30ms); A_DS(DS, T#30ms); A_SL(SL, T#30ms); END_STEP
      sfc::STEP<&P::S2, sfc::SD<&P::A_SD, "T#30ms">, sfc::DS<&P::A_DS, "T#30ms">, sfc::SL<&P::A_SL, "T#30ms">>,
      // TRANSITION FROM S2 TO S3 := NEXT; END_TRANSITION
      sfc::TRANSITION<sfc::FROM<&P::S2>, sfc::TO<&P::S3>, &P::NEXT>,
      // STEP S3: END_STEP
      sfc::STEP<&P::S3>,
      // TRANSITION FROM S3 TO S4 := NEXT; END_TRANSITION
      sfc::TRANSITION<sfc::FROM<&P::S3>, sfc::TO<&P::S4>, &P::NEXT>,
      // STEP S4: A_SD(R); A_DS(R); A_SL(R); END_STEP
      sfc::STEP<&P::S4, sfc::R<&P::A_SD>, sfc::R<&P::A_DS>, sfc::R<&P::A_SL>>,
      // TRANSITION FROM S4 TO INIT := NEXT; END_TRANSITION
      sfc::TRANSITION<sfc::FROM<&P::S4>, sfc::TO<&P::INIT>, &P::NEXT>>
      chart;

  void body() { chart(*this); }
};
// END_PROGRAM

}  // namespace sfc_reference
