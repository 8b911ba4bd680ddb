// The scheduler in simulated time: how fast an hour of machine time runs, and what one task
// cycle costs on top of the programs it calls.
//
//   BM_SimulatedHour_1msTask_100Blocks  one iteration = one simulated hour of a 1 ms task
//                                       whose program calls 100 standard blocks
//                                       (25 x TON, CTU, R_TRIG, SR) — target: well under 1 s
//   BM_TaskCycle/<n>                    n tasks of one empty program, all due every 1 ms;
//                                       ns_per_task_cycle is the scheduler's own cost
#include <benchmark/benchmark.h>

#include <array>
#include <cstddef>
#include <utility>

#include <iecoop/iecoop.hpp>

namespace {

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

void BM_SimulatedHour_1msTask_100Blocks(benchmark::State& state) {
  application plc{task<CELLS_PRG>{"Main", cyclic{"T#1ms"_iec}, 1}};
  plc.start();
  for (auto _ : state) {
    plc.run_for("T#1h"_iec);
    benchmark::DoNotOptimize(CELLS_PRG::instance().nOn.get());
  }
  const auto cycles = static_cast<double>(plc.task(0).statistics().cycles);
  state.counters["task_cycles"] = cycles;
  state.counters["ns_per_task_cycle"] = benchmark::Counter(cycles, benchmark::Counter::kIsRate | benchmark::Counter::kInvert);
  state.counters["simulated_s_per_s"] = benchmark::Counter(3600.0 * static_cast<double>(state.iterations()), benchmark::Counter::kIsRate);
}
BENCHMARK(BM_SimulatedHour_1msTask_100Blocks)->Unit(benchmark::kMillisecond)->Iterations(3);

// PROGRAM EMPTY_PRG: nothing, so that only the scheduler is measured.
struct EMPTY_PRG : program<EMPTY_PRG> {
  void body() { benchmark::ClobberMemory(); }
};

template <std::size_t... I>
auto tasks_of_empty_program(std::index_sequence<I...>) {
  return application{(void(I), task<EMPTY_PRG>{"T", cyclic{"T#1ms"_iec}, 1})...};
}

template <std::size_t N>
void BM_TaskCycle(benchmark::State& state) {
  auto plc = tasks_of_empty_program(std::make_index_sequence<N>{});
  plc.start();
  for (auto _ : state) plc.run_for("T#1ms"_iec);
  state.counters["ns_per_task_cycle"] =
      benchmark::Counter(static_cast<double>(N) * static_cast<double>(state.iterations()), benchmark::Counter::kIsRate | benchmark::Counter::kInvert);
}
BENCHMARK(BM_TaskCycle<1>);
BENCHMARK(BM_TaskCycle<8>);
BENCHMARK(BM_TaskCycle<32>);

}  // namespace
