#!/bin/sh
# Measures iecoop's performance and writes docs/performance.md: builds the benchmarks in
# Release, runs every Google Benchmark (5 repetitions, medians), counts instructions per
# kernel with callgrind (bench/callgrind.sh), and renders the figures, the ratios against
# the hand-written equivalents, the machine, the compiler and the flags.
# Installs the Debian packages it needs first. Takes a few minutes; run it on a quiet machine.
set -eu
cd "$(dirname "$0")/.."
. tools/require_packages.sh
iecoop_require_packages cmake make g++ libbenchmark-dev valgrind python3

out=build/report
jobs=$(iecoop_jobs)
cmake -S . -B "$out" -DCMAKE_BUILD_TYPE=Release -DIECOOP_WERROR=ON \
  -DIECOOP_BUILD_BENCH=ON >/dev/null
cmake --build "$out" --target iecoop_bench iecoop_bench_count -j "$jobs" >/dev/null

echo "== iecoop: running the benchmarks" >&2
"$out/bench/iecoop_bench" --benchmark_repetitions=5 --benchmark_report_aggregates_only=true \
  --benchmark_out="$out/bench.json" --benchmark_out_format=json >&2
echo "== iecoop: counting instructions with callgrind" >&2
sh bench/callgrind.sh "$out/bench/iecoop_bench_count" >"$out/callgrind.txt"

{
  echo "cpu=$(sed -n 's/^model name[[:space:]]*: //p' /proc/cpuinfo | head -n 1)"
  echo "cores=$(nproc 2>/dev/null || echo '?')"
  echo "memory=$(awk '/MemTotal/ { printf "%.0f GiB", $2 / 1048576 }' /proc/meminfo)"
  echo "os=$(. /etc/os-release && echo "$PRETTY_NAME")"
  echo "compiler=$(g++ --version | head -n 1)"
  echo "flags=$(sed -n 's/^CMAKE_CXX_FLAGS_RELEASE:[A-Z]*=//p' "$out/CMakeCache.txt") -std=c++20 (-Wall -Wextra -Wpedantic -Werror and iecoop's warnings)"
  echo "benchmark=libbenchmark $(dpkg-query -W -f='${Version}' libbenchmark-dev 2>/dev/null || echo '?')"
  echo "valgrind=$(valgrind --version)"
  echo "commit=$(git rev-parse --short HEAD 2>/dev/null || echo '?')"
} >"$out/machine.txt"

python3 bench/report.py "$out/bench.json" "$out/callgrind.txt" "$out/machine.txt" >docs/performance.md
echo "== iecoop: wrote docs/performance.md" >&2
