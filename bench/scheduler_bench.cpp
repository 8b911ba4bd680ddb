// The scheduler in simulated time: how fast an hour of machine time runs, and what one task
// cycle costs on top of the programs it calls — each against a hand-written equivalent.
//
//   BM_SimulatedHour_1msTask_100Blocks         one iteration = one simulated hour of a 1 ms
//                                              task whose program calls 100 standard blocks
//                                              (25 x TON, CTU, R_TRIG, SR) — target < 1 s
//   BM_SimulatedHour_1msLoop_100Blocks         the same program called by a plain loop that
//                                              sets the cycle clock (no scheduler)
//   BM_TaskCycle<n>                            n tasks of one empty program, all due every
//                                              1 ms; ns_per_task_cycle — target <= 50 ns
//   BM_TaskCycle_handwritten<n>                the same with a hand-written cyclic executive
#include <benchmark/benchmark.h>

#include <cstddef>
#include <cstdint>
#include <utility>

#include "scheduler_programs.hpp"

namespace {

using namespace scheduler_programs;

constexpr std::uint64_t cycles_per_hour = 3'600'000;

void BM_SimulatedHour_1msTask_100Blocks(benchmark::State& state) {
  application plc{task<CELLS_PRG>{"Main", cyclic{"T#1ms"_iec}, 1}};
  plc.start();
  for (auto _ : state) {
    plc.run_for("T#1h"_iec);
    benchmark::DoNotOptimize(CELLS_PRG::instance().nOn.get());
  }
  const auto cycles = static_cast<double>(plc.task(0).statistics().cycles);
  state.counters["task_cycles"] = cycles;
  state.counters["ns_per_task_cycle"] =
      benchmark::Counter(cycles, benchmark::Counter::kIsRate | benchmark::Counter::kInvert);
  state.counters["simulated_cycles_per_s"] = benchmark::Counter(cycles, benchmark::Counter::kIsRate);
}
BENCHMARK(BM_SimulatedHour_1msTask_100Blocks)->Unit(benchmark::kMillisecond)->Iterations(3);

void BM_SimulatedHour_1msLoop_100Blocks(benchmark::State& state) {
  CELLS_PRG prg;
  LTIME now{};
  for (auto _ : state) {
    for (std::uint64_t c = 0; c < cycles_per_hour; ++c) {
      cycle_clock::set(now);
      prg();
      now += "T#1ms"_iec;
    }
    benchmark::DoNotOptimize(prg.nOn.get());
  }
  const auto cycles = static_cast<double>(cycles_per_hour) * static_cast<double>(state.iterations());
  state.counters["task_cycles"] = cycles;
  state.counters["ns_per_task_cycle"] =
      benchmark::Counter(cycles, benchmark::Counter::kIsRate | benchmark::Counter::kInvert);
  state.counters["simulated_cycles_per_s"] = benchmark::Counter(cycles, benchmark::Counter::kIsRate);
}
BENCHMARK(BM_SimulatedHour_1msLoop_100Blocks)->Unit(benchmark::kMillisecond)->Iterations(3);

template <std::size_t N>
void BM_TaskCycle(benchmark::State& state) {
  auto plc = tasks_of_empty_program(std::make_index_sequence<N>{});
  plc.start();
  for (auto _ : state) plc.run_for("T#1ms"_iec);
  state.counters["ns_per_task_cycle"] =
      benchmark::Counter(static_cast<double>(N) * static_cast<double>(state.iterations()),
                         benchmark::Counter::kIsRate | benchmark::Counter::kInvert);
}
BENCHMARK(BM_TaskCycle<1>);
BENCHMARK(BM_TaskCycle<8>);
BENCHMARK(BM_TaskCycle<32>);

template <std::size_t N>
void BM_TaskCycle_handwritten(benchmark::State& state) {
  handwritten_executive<N> executive;
  for (auto _ : state) executive.run_for(1'000'000);
  state.counters["ns_per_task_cycle"] =
      benchmark::Counter(static_cast<double>(N) * static_cast<double>(state.iterations()),
                         benchmark::Counter::kIsRate | benchmark::Counter::kInvert);
}
BENCHMARK(BM_TaskCycle_handwritten<1>);
BENCHMARK(BM_TaskCycle_handwritten<8>);
BENCHMARK(BM_TaskCycle_handwritten<32>);

}  // namespace
