// One scan of a 20-step SFC chart (sfc::chart, codesys order: a simultaneous divergence and
// convergence, N, S, R and L actions) against the switch-based state machine written by hand
// for the same behaviour (sfc_programs.hpp); both driven by the same inputs, scan k at k x 10 ms.
//
//   BM_Sfc_chart         P_BATCH(): the chart's scan, after the clock and the inputs
//   BM_Sfc_handwritten   hand_batch::scan, after the time stamp and the inputs
//   BM_Sfc_paired        the two, taking turns in batches of 1000 scans (<P_BATCH>: the chart on
//                        the compiled engine; <P_BATCH_GENERAL>: on the general engine)
//
// Counters: ns_per_scan; the paired one chart_ns, handwritten_ns and ratio, the medians over
// the batches of each side's time per scan and of the ratio of two neighbouring batches (a
// shared machine's slow spells slow both). Each benchmark first checks that both sides produce
// the same outputs over sfc_programs::check_scans scans. Run in one process, interleaved:
//
//   iecoop_bench_sfc --benchmark_repetitions=10 --benchmark_enable_random_interleaving=true
//                    --benchmark_report_aggregates_only=true
//
// Instruction counts: sh bench/callgrind.sh iecoop_bench_sfc_count (sfc_count.cpp).
#include <benchmark/benchmark.h>

#include <algorithm>
#include <chrono>
#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

#include "sfc_programs.hpp"

namespace {

using namespace sfc_programs;

bool twins_agree(benchmark::State& state) {
  std::uint32_t sequences = 0;
  const std::uint32_t agreed = check(sequences);
  if (agreed == check_scans) return true;
  state.SkipWithError(("the chart and the hand-written machine differ after scan " + std::to_string(agreed)).c_str());
  return false;
}

void per_scan(benchmark::State& state) {
  state.counters["ns_per_scan"] = benchmark::Counter(static_cast<double>(state.iterations()),
                                                     benchmark::Counter::kIsRate | benchmark::Counter::kInvert);
}

void BM_Sfc_chart(benchmark::State& state) {
  if (!twins_agree(state)) return;
  P_BATCH p;
  std::uint32_t k = 0;
  for (auto _ : state) {
    chart_scan(p, k++);
    benchmark::ClobberMemory();
  }
  benchmark::DoNotOptimize(p.C_DONE.value());
  per_scan(state);
}

void BM_Sfc_handwritten(benchmark::State& state) {
  if (!twins_agree(state)) return;
  hand_batch h{};
  std::uint32_t k = 0;
  for (auto _ : state) {
    hand_scan(h, k++);
    benchmark::ClobberMemory();
  }
  benchmark::DoNotOptimize(h.C_DONE);
  per_scan(state);
}

double median(std::vector<double> v) {
  if (v.empty()) return 0;
  const auto mid = v.begin() + static_cast<std::ptrdiff_t>(v.size() / 2);
  std::nth_element(v.begin(), mid, v.end());
  return *mid;
}

// Batches of chart and hand-written scans in turn (each side first every other time), timed
// apart; the benchmark's time is both sides'.
template <class Chart>
void BM_Sfc_paired(benchmark::State& state) {
  if (!twins_agree(state)) return;
  using clock = std::chrono::steady_clock;
  constexpr int batch = 1000;
  Chart p;
  hand_batch h{};
  std::uint32_t kc = 0;
  std::uint32_t kh = 0;
  const auto run = [](auto&& scan) {
    const clock::time_point start = clock::now();
    for (int i = 0; i < batch; ++i) {
      scan();
      benchmark::ClobberMemory();
    }
    return std::chrono::duration<double, std::nano>(clock::now() - start).count() / batch;
  };
  const auto chart_side = [&] { return run([&] { chart_scan(p, kc++); }); };
  const auto hand_side = [&] { return run([&] { hand_scan(h, kh++); }); };
  std::vector<double> chart_ns;
  std::vector<double> hand_ns;
  std::vector<double> ratio;
  bool chart_first = true;
  for (auto _ : state) {
    double c = 0;
    double w = 0;
    if (chart_first) {
      c = chart_side();
      w = hand_side();
    } else {
      w = hand_side();
      c = chart_side();
    }
    chart_first = !chart_first;
    chart_ns.push_back(c);
    hand_ns.push_back(w);
    ratio.push_back(c / w);
    state.SetIterationTime((c + w) * batch * 1e-9);
  }
  benchmark::DoNotOptimize(p.C_DONE.value());
  benchmark::DoNotOptimize(h.C_DONE);
  state.counters["chart_ns"] = median(chart_ns);
  state.counters["handwritten_ns"] = median(hand_ns);
  state.counters["ratio"] = median(ratio);
}

BENCHMARK(BM_Sfc_chart);
BENCHMARK(BM_Sfc_handwritten);
BENCHMARK(BM_Sfc_paired<P_BATCH>)->UseManualTime();
BENCHMARK(BM_Sfc_paired<P_BATCH_GENERAL>)->UseManualTime();

}  // namespace
