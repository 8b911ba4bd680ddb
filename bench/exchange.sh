#!/bin/sh
# The data exchange's figures (docs/exchange.md, "Cost"): what the Modbus drivers add to a task
# cycle by the number of mapped words, and whether network traffic moves a 1 ms task's timing.
#
#   sh bench/exchange.sh [-c COMPILER] [-p PHASES] [-s SECONDS] [-k CLIENTS]
#
# A Release build (default g++) in build/exchange-<compiler>; then iecoop_bench_exchange with 5
# repetitions (the medians, as a Markdown table) and iecoop_exchange_jitter with PHASES quiet and
# PHASES traffic phases of SECONDS each (default 3 x 2 s) and CLIENTS clients (default 2).
# Installs what it needs (cmake, the compiler, Google Benchmark, pkg-config, libmodbus, libmosquitto)
# first.
set -eu
cd "$(dirname "$0")/.."
. tools/require_packages.sh

compiler=g++
phases=3
seconds=2
clients=2
while getopts c:p:s:k: option; do
  case $option in
    c) compiler=$OPTARG ;;
    p) phases=$OPTARG ;;
    s) seconds=$OPTARG ;;
    k) clients=$OPTARG ;;
    *) echo "usage: sh bench/exchange.sh [-c COMPILER] [-p PHASES] [-s SECONDS] [-k CLIENTS]" >&2; exit 2 ;;
  esac
done
iecoop_require_packages cmake make g++ libbenchmark-dev pkg-config libmodbus-dev libmosquitto-dev

dir=build/exchange-$compiler
echo "== exchange: building with $compiler in $dir" >&2
cmake -S . -B "$dir" -DCMAKE_CXX_COMPILER="$compiler" -DCMAKE_BUILD_TYPE=Release -DIECOOP_BUILD_BENCH=ON \
  -DIECOOP_BUILD_TESTS=OFF -DIECOOP_BUILD_EXAMPLES=OFF -DIECOOP_BUILD_TOOLS=OFF -DIECOOP_BUILD_CHECK=OFF \
  -DIECOOP_INSTALL=OFF >/dev/null
cmake --build "$dir" -j "$(iecoop_jobs)" --target iecoop_bench_exchange iecoop_exchange_jitter >/dev/null

echo "== exchange: the cycle's cost (5 repetitions, medians)" >&2
echo "| Benchmark | Words each way (MQTT: channels) | ns per cycle | ns per word (channel) |"
echo "|---|---:|---:|---:|"
"$dir/bench/iecoop_bench_exchange" --benchmark_repetitions=5 --benchmark_report_aggregates_only=true \
  --benchmark_format=csv 2>/dev/null |
  awk -F, '/_median"/ {
    name = $1; gsub(/"/, "", name); sub(/_median$/, "", name); sub(/\/real_time$/, "", name)
    n = split(name, part, "/")
    printf "| %s | %s | %.1f | %.3f |\n", part[1], part[n], $3, $3 / part[n]
  }'

echo "== exchange: the task's timing, quiet and under traffic" >&2
"$dir/bench/iecoop_exchange_jitter" --phases "$phases" --seconds "$seconds" --clients "$clients"
