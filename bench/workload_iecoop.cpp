// The standard scan workload (workload.hpp) written with iecoop, as a PLC engineer ports the
// Structured Text: a PROGRAM whose cells are a STRUCT of the standard blocks.
#include "workload.hpp"

#include <chrono>
#include <cstddef>
#include <cstdint>
#include <optional>

#include <iecoop/iecoop.hpp>

namespace workload::iecoop_side {
namespace {

using namespace iecoop;

// TYPE CELL : STRUCT
//   T : TON;  C : CTU;  E : R_TRIG;
// END_STRUCT END_TYPE
struct CELL {
  TON T;
  iec::CTU C;  // the IEC dialect's CTU: INT counter with input R, as the ST above writes it
  R_TRIG E;
};

// PROGRAM WORKLOAD_PRG
// VAR
//   CELLS : ARRAY[0..999] OF CELL;
//   CYC, NTON, NCTU, NEDGE, ACC, PH : INT;
// END_VAR
struct WORKLOAD_PRG : program<WORKLOAD_PRG> {
  ARRAY<CELL, 0, 999> CELLS;
  INT CYC;
  INT NTON;
  INT NCTU;
  INT NEDGE;
  INT ACC;
  INT PH;

  void body() {
    CYC = (CYC + 1) % 24000;          // CYC := (CYC + 1) MOD 24000;
    NTON = 0;                         // NTON := 0;
    NCTU = 0;                         // NCTU := 0;
    NEDGE = 0;                        // NEDGE := 0;
    for (INT K = 0; K <= 999; ++K) {  // FOR K := 0 TO 999 DO
      CELL& cell = CELLS[K];
      PH = (CYC + K) % 20;                              //   PH := (CYC + K) MOD 20;
      cell.T("IN"_ = PH < 15, "PT"_ = "T#50ms"_iec);    //   CELLS[K].T(IN := PH < 15, PT := T#50ms);
      if (cell.T.Q) NTON = NTON + 1;                    //   IF CELLS[K].T.Q THEN NTON := NTON + 1; END_IF;
      cell.C("CU"_ = PH % 4 < 2,                        //   CELLS[K].C(CU := (PH MOD 4) < 2,
             "R"_ = (CYC + K) % 500 == 0, "PV"_ = 50);  //              R := ((CYC + K) MOD 500) = 0, PV := 50);
      if (cell.C.Q) NCTU = NCTU + 1;                    //   IF CELLS[K].C.Q THEN NCTU := NCTU + 1; END_IF;
      cell.E("CLK"_ = (CYC + 3 * K) % 6 < 3);           //   CELLS[K].E(CLK := ((CYC + 3 * K) MOD 6) < 3);
      if (cell.E.Q) NEDGE = NEDGE + 1;                  //   IF CELLS[K].E.Q THEN NEDGE := NEDGE + 1; END_IF;
      ACC = (ACC * 3 + K * 3 - PH) % 8191;              //   ACC := (ACC * 3 + K * 3 - PH) MOD 8191;
    }                                                   // END_FOR
  }
};

// The program's one instance (an application would own it; here the driver runs it). A
// PROGRAM has one instance at a time, so reset() ends it before it makes a fresh one.
std::optional<WORKLOAD_PRG> the_program{std::in_place};

}  // namespace

void reset() noexcept {
  the_program.reset();
  the_program.emplace();
}

void scan(std::uint32_t k) noexcept {
  cycle_clock::set(std::chrono::milliseconds{std::int64_t{k} * scan_period_ms});
  (*the_program)();
}

readings read() noexcept {
  const WORKLOAD_PRG& p = *the_program;
  return {p.NTON.value(), p.NCTU.value(), p.NEDGE.value(), p.ACC.value()};
}

}  // namespace workload::iecoop_side
