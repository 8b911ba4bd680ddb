// The cost of recording a trace: one cycle of a program of 16 BOOLs and 8 INTs that all change
// every cycle, sampled into a trace_recorder (trace_programs.hpp), against the same cycle
// without the recorder. The difference is what recording costs per cycle — target < 50 ns.
//
//   BM_TraceCycle_untraced                     the program alone (the baseline)
//   BM_TraceCycle_every_cycle                  + a sample every cycle (trace_mode::every_cycle)
//   BM_TraceCycle_every_cycle_trigger_armed    + the same, waiting for a trigger
//   BM_TraceCycle_on_change                    + trace_mode::on_change, a sample stored every
//                                                cycle (something changed)
//   BM_TraceCycle_on_change_unchanged          trace_mode::on_change, nothing changed: the
//                                                sample is compared and dropped (no program)
//   BM_TraceTask_untraced / _traced            a 1 ms task of the program in an application,
//                                                without / with the recorder attached to it
//
// Counters: ns_per_cycle, and sample_bytes (the memory one sample takes: 12 bytes of time and
// cycle, one bit per BOOL, each INT in its 2 bytes: 30).
#include <benchmark/benchmark.h>

#include <memory>

#include "trace_programs.hpp"

namespace {

using namespace trace_programs;

void run(benchmark::State& state, recording how) {
  auto traced = std::make_unique<traced_program>(how);
  for (auto _ : state) {
    traced->run_cycle();
    benchmark::ClobberMemory();
  }
  state.counters["ns_per_cycle"] = benchmark::Counter(static_cast<double>(state.iterations()),
                                                      benchmark::Counter::kIsRate | benchmark::Counter::kInvert);
  if (how != recording::none) state.counters["sample_bytes"] = static_cast<double>(traced->trace.sample_bytes());
  benchmark::DoNotOptimize(traced->trace.size());
}

void BM_TraceCycle_untraced(benchmark::State& state) { run(state, recording::none); }
void BM_TraceCycle_every_cycle(benchmark::State& state) { run(state, recording::every_cycle); }
void BM_TraceCycle_every_cycle_trigger_armed(benchmark::State& state) {
  run(state, recording::every_cycle_trigger_armed);
}
void BM_TraceCycle_on_change(benchmark::State& state) { run(state, recording::on_change); }
void BM_TraceCycle_on_change_unchanged(benchmark::State& state) { run(state, recording::on_change_unchanged); }
BENCHMARK(BM_TraceCycle_untraced);
BENCHMARK(BM_TraceCycle_every_cycle);
BENCHMARK(BM_TraceCycle_every_cycle_trigger_armed);
BENCHMARK(BM_TraceCycle_on_change);
BENCHMARK(BM_TraceCycle_on_change_unchanged);

// The same program as a 1 ms task: the scheduler's cycle, and the recorder called by the task
// after the program (cycle_observer) when attached.
void run_task(benchmark::State& state, bool traced) {
  application plc{task<SIGNALS_PRG>{"Fast", cyclic{"T#1ms"_iec}, 1}};
  auto trace = std::make_unique<trace_recorder<64 * 1024, 32>>();
  plc.start();
  if (traced) {
    add_channels(*trace, plc.get<SIGNALS_PRG>());
    trace->attach(plc.task("Fast"));
    trace->start();
  }
  for (auto _ : state) plc.run_for("T#1ms"_iec);
  state.counters["ns_per_cycle"] = benchmark::Counter(static_cast<double>(state.iterations()),
                                                      benchmark::Counter::kIsRate | benchmark::Counter::kInvert);
  if (traced) state.counters["sample_bytes"] = static_cast<double>(trace->sample_bytes());
  benchmark::DoNotOptimize(trace->size());
  trace->detach();
  plc.stop();
}
void BM_TraceTask_untraced(benchmark::State& state) { run_task(state, false); }
void BM_TraceTask_traced(benchmark::State& state) { run_task(state, true); }
BENCHMARK(BM_TraceTask_untraced);
BENCHMARK(BM_TraceTask_traced);

}  // namespace
