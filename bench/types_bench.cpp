// Wrap-around IEC integer arithmetic against the built-in integer it wraps: the IEC type
// must cost nothing (compare the two figures of one run).
#include <benchmark/benchmark.h>

#include <cstdint>
#include <iecoop/types/elementary.hpp>

namespace {

template <class T>
void accumulate(benchmark::State& state) {
  T acc{};
  T step = T(7);
  for (auto _ : state) {
    benchmark::DoNotOptimize(step);
    acc = acc * T(3) + step;
    benchmark::DoNotOptimize(acc);
  }
}

void BM_DintArithmetic_iecoop(benchmark::State& state) { accumulate<iecoop::DINT>(state); }
// The hand-written twin uses unsigned arithmetic, the only UB-free way in C++.
void BM_DintArithmetic_builtin(benchmark::State& state) { accumulate<std::uint32_t>(state); }

}  // namespace

BENCHMARK(BM_DintArithmetic_iecoop);
BENCHMARK(BM_DintArithmetic_builtin);
