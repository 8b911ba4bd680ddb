// What the test kit adds to a cycle when a test only steps time (testing_programs.hpp): each
// driver against the loop it replaces, one cycle per call, so that the difference is the kit's
// cost per cycle — target: a few ns.
//
//   BM_Kit_cycles_step         testing::cycles over FB_Blink, run.step() per cycle
//   BM_Kit_cycles_handwritten  cycle_clock::set(now); fbBlink(); now += T#1ms;
//   BM_Kit_plc_step            testing::plc<make_blink<>>, plc.step() per base cycle (T#1ms)
//   BM_Kit_plc_run_for         the same application, app.run_for(app.base_cycle())
//   BM_Kit_cycles_paired       the first two, taking turns in batches of 1000 cycles
//   BM_Kit_plc_paired          the last two, likewise (two copies of the application)
//
// Counters: ns_per_cycle; the paired ones kit_ns, handwritten_ns and added_ns, the medians over
// the batches of each side's time per cycle and of the difference of two neighbouring batches
// (a shared machine's slow spells slow both). Run in one process, the sides interleaved:
//
//   iecoop_bench_testing --benchmark_repetitions=10 --benchmark_enable_random_interleaving=true
//                        --benchmark_report_aggregates_only=true
//
// Instruction counts: sh bench/callgrind.sh iecoop_bench_testing_count (testing_count.cpp).
#define DOCTEST_CONFIG_IMPLEMENT  // doctest's code, which the kit calls, without doctest's main()

#include <benchmark/benchmark.h>

#include <algorithm>
#include <chrono>
#include <cstddef>
#include <vector>

#include "testing_programs.hpp"

namespace {

using namespace testing_programs;

void per_cycle(benchmark::State& state) {
  state.counters["ns_per_cycle"] = benchmark::Counter(static_cast<double>(state.iterations()),
                                                      benchmark::Counter::kIsRate | benchmark::Counter::kInvert);
}

void BM_Kit_cycles_step(benchmark::State& state) {
  FB_Blink fb;
  testing::cycles run{fb, cycle_time};
  for (auto _ : state) {
    run.step();
    benchmark::ClobberMemory();
  }
  benchmark::DoNotOptimize(fb.nToggles.get());
  per_cycle(state);
}

void BM_Kit_cycles_handwritten(benchmark::State& state) {
  FB_Blink fb;
  LTIME now{};
  for (auto _ : state) {
    cycle_clock::set(now);
    fb();
    now = now + cycle_time;
    benchmark::ClobberMemory();
  }
  benchmark::DoNotOptimize(fb.nToggles.get());
  per_cycle(state);
}

void BM_Kit_plc_step(benchmark::State& state) {
  testing::plc<make_blink<>> plc;
  for (auto _ : state) {
    plc.step();
    benchmark::ClobberMemory();
  }
  benchmark::DoNotOptimize(plc.get<BLINK_PRG<0>>().fbBlink.nToggles.get());
  per_cycle(state);
}

void BM_Kit_plc_run_for(benchmark::State& state) {
  auto app = make_blink();
  app.start();
  for (auto _ : state) {
    app.run_for(app.base_cycle());
    benchmark::ClobberMemory();
  }
  benchmark::DoNotOptimize(app.get<BLINK_PRG<0>>().fbBlink.nToggles.get());
  app.stop();
  per_cycle(state);
}

double median(std::vector<double> v) {
  if (v.empty()) return 0;
  const auto mid = v.begin() + static_cast<std::ptrdiff_t>(v.size() / 2);
  std::nth_element(v.begin(), mid, v.end());
  return *mid;
}

// Batches of `kit` and `handwritten` cycles in turn (each side first every other time), timed
// apart; the benchmark's time is both sides'.
template <class Kit, class Handwritten>
void paired(benchmark::State& state, Kit kit, Handwritten handwritten) {
  using clock = std::chrono::steady_clock;
  constexpr int batch = 1000;
  const auto run = [](auto& side) {
    const clock::time_point start = clock::now();
    for (int i = 0; i < batch; ++i) {
      side();
      benchmark::ClobberMemory();
    }
    return std::chrono::duration<double, std::nano>(clock::now() - start).count() / batch;
  };
  std::vector<double> kit_ns;
  std::vector<double> handwritten_ns;
  std::vector<double> added_ns;
  bool kit_first = true;
  for (auto _ : state) {
    double k = 0;
    double h = 0;
    if (kit_first) {
      k = run(kit);
      h = run(handwritten);
    } else {
      h = run(handwritten);
      k = run(kit);
    }
    kit_first = !kit_first;
    kit_ns.push_back(k);
    handwritten_ns.push_back(h);
    added_ns.push_back(k - h);
    state.SetIterationTime((k + h) * batch * 1e-9);
  }
  state.counters["kit_ns"] = median(kit_ns);
  state.counters["handwritten_ns"] = median(handwritten_ns);
  state.counters["added_ns"] = median(added_ns);
}

void BM_Kit_cycles_paired(benchmark::State& state) {
  FB_Blink fb_kit;
  testing::cycles run{fb_kit, cycle_time};
  FB_Blink fb;
  LTIME now{};
  paired(
      state, [&] { run.step(); },
      [&] {
        cycle_clock::set(now);
        fb();
        now = now + cycle_time;
      });
  benchmark::DoNotOptimize(fb_kit.nToggles.get());
  benchmark::DoNotOptimize(fb.nToggles.get());
}

void BM_Kit_plc_paired(benchmark::State& state) {
  testing::plc<make_blink<0>> plc;
  auto app = make_blink<1>();
  app.start();
  paired(
      state, [&] { plc.step(); }, [&] { app.run_for(app.base_cycle()); });
  benchmark::DoNotOptimize(plc.get<BLINK_PRG<0>>().fbBlink.nToggles.get());
  benchmark::DoNotOptimize(app.get<BLINK_PRG<1>>().fbBlink.nToggles.get());
  app.stop();
}

BENCHMARK(BM_Kit_cycles_step);
BENCHMARK(BM_Kit_cycles_handwritten);
BENCHMARK(BM_Kit_plc_step);
BENCHMARK(BM_Kit_plc_run_for);
BENCHMARK(BM_Kit_cycles_paired)->UseManualTime();
BENCHMARK(BM_Kit_plc_paired)->UseManualTime();

}  // namespace
