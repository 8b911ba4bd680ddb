// The standard scan workload (workload.hpp): one scan per iteration, iecoop against the
// hand-written version in the same run (and the lean variant that does not store the
// blocks' inputs). Before a benchmark reports anything, it checks that its implementation
// reproduces the workload's figures over 100000 scans; a wrong one reports an error.
//
//   ./iecoop_bench --benchmark_filter=BM_Workload
#include <benchmark/benchmark.h>

#include <cstdint>

#include "workload.hpp"

namespace {

using namespace workload;

template <class Reset, class Scan, class Read>
void run_workload(benchmark::State& state, bool checked, Reset reset, Scan scan, Read read) {
  if (!checked) {
    state.SkipWithError("the implementation does not reproduce the workload's cross-check figures");
    return;
  }
  reset();
  std::uint32_t k = 0;
  for (auto _ : state) scan(k++);
  benchmark::DoNotOptimize(read());
  state.counters["cells_per_scan"] = 1000;
}

void BM_Workload_iecoop(benchmark::State& state) {
  static const bool checked = cross_check(iecoop_side::reset, iecoop_side::scan, iecoop_side::read);  // once per run
  run_workload(state, checked, iecoop_side::reset, iecoop_side::scan, iecoop_side::read);
}
void BM_Workload_handwritten(benchmark::State& state) {
  static const bool checked =
      cross_check(handwritten_side::reset, handwritten_side::scan, handwritten_side::read);  // once per run
  run_workload(state, checked, handwritten_side::reset, handwritten_side::scan, handwritten_side::read);
}
void BM_Workload_handwritten_minimal(benchmark::State& state) {
  static const bool checked = cross_check(minimal_side::reset, minimal_side::scan, minimal_side::read);  // once per run
  run_workload(state, checked, minimal_side::reset, minimal_side::scan, minimal_side::read);
}

}  // namespace

BENCHMARK(BM_Workload_iecoop)->Unit(benchmark::kMicrosecond);
BENCHMARK(BM_Workload_handwritten)->Unit(benchmark::kMicrosecond);
BENCHMARK(BM_Workload_handwritten_minimal)->Unit(benchmark::kMicrosecond);
