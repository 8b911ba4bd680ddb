// The Google Benchmark runner for iecoop_bench.
#include <benchmark/benchmark.h>

BENCHMARK_MAIN();
