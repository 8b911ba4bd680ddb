// The programs the scheduler benchmarks run (scheduler_bench.cpp, count_main.cpp).
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>

#include <iecoop/iecoop.hpp>

namespace scheduler_programs {

using namespace iecoop;

// FUNCTION_BLOCK FB_Cell: four standard blocks driven by a phase.
struct FB_Cell : function_block<FB_Cell> {
  INT iPhase;
  BOOL bOut;
  using VAR_INPUT = pins<&FB_Cell::iPhase>;
  using VAR_OUTPUT = pins<&FB_Cell::bOut>;

  TON tDelay;
  CTU cParts;
  R_TRIG rEdge;
  SR sLatch;

  void body() {
    const BOOL on = BOOL(iPhase < 15);
    tDelay("IN"_ = on, "PT"_ = 5);
    cParts("CU"_ = BOOL(iPhase % 4 < 2), "RESET"_ = BOOL(iPhase == 0), "PV"_ = 50);
    rEdge("CLK"_ = tDelay.Q);
    sLatch("S1"_ = rEdge.Q, "R"_ = cParts.Q);
    bOut = sLatch.Q1;
  }
};

// PROGRAM CELLS_PRG: 25 cells = 100 blocks.
struct CELLS_PRG : program<CELLS_PRG> {
  std::array<FB_Cell, 25> cells;
  var<INT> iCycle;
  var<DINT> nOn;
  void body() {
    iCycle = (iCycle + 1) % 20;
    for (std::size_t k = 0; k < cells.size(); ++k) {
      FB_Cell& cell = cells[k];
      cell("iPhase"_ = INT((iCycle + INT(static_cast<std::int16_t>(k))) % 20));
      if (cell.bOut) nOn = nOn + 1;
    }
  }
};

// PROGRAM EMPTY_PRG: nothing (but a memory access the optimiser keeps), so that only the
// scheduler is measured.
inline volatile std::uint32_t empty_program_calls = 0;
struct EMPTY_PRG : program<EMPTY_PRG> {
  void body() { empty_program_calls = empty_program_calls + 1; }
};

/// An application of n tasks, each calling EMPTY_PRG every 1 ms at the same priority.
template <std::size_t... I>
auto tasks_of_empty_program(std::index_sequence<I...>) {
  return application{(void(I), task<EMPTY_PRG>{"T", cyclic{"T#1ms"_iec}, 1})...};
}

/// The hand-written equivalent of such an application: a cyclic executive that keeps each
/// task's next release and calls the due ones in order.
template <std::size_t N>
struct handwritten_executive {
  struct entry {
    std::uint64_t next_ns;
    std::uint64_t interval_ns;
  };
  std::array<entry, N> tasks{};
  std::uint64_t now_ns = 0;

  handwritten_executive() {
    for (entry& e : tasks) e = {0, 1'000'000};
  }
  void run_for(std::uint64_t ns) {
    const std::uint64_t until = now_ns + ns;
    while (true) {
      std::uint64_t next = UINT64_MAX;
      for (entry& e : tasks) {
        if (e.next_ns <= now_ns) {
          empty_program_calls = empty_program_calls + 1;
          e.next_ns += e.interval_ns;
        }
        if (e.next_ns < next) next = e.next_ns;
      }
      if (next >= until) break;
      now_ns = next;
    }
    now_ns = until;
  }
};

}  // namespace scheduler_programs
