#!/bin/sh
# The zero-overhead figure on several compilers: the workload's scan with iecoop against its
# hand-written twin (bench/workload.hpp), in time and in instructions.
#
#   sh bench/ratio.sh [-p PROCESSES] [-r REPS] [COMPILER...]
#
# For each compiler (default: g++ clang++-14 clang++-16) a Release build of the two programs it
# needs in build/ratio-<compiler>; then PROCESSES runs (default 5) of iecoop_workload_ratio with
# REPS repetitions each (default 201), the compilers taking turns, so that the machine's slow
# spells fall on all of them; then callgrind's instructions per scan of each side
# (bench/callgrind.sh). Prints a Markdown table: the median over the processes of each
# process's median ratio, the range of those medians, the median of the processes' 10th and
# 90th percentiles of the repetitions' ratios, and the instruction ratios (also against the
# hand-written variant that does not store the blocks' inputs, workload_minimal.cpp). The
# table's first line names the CPU (lscpu's model name), the date and the commit.
# Installs what it needs (g++, clang-14, clang-16, Google Benchmark, valgrind) first.
set -eu
cd "$(dirname "$0")/.."
. tools/require_packages.sh

processes=5
reps=201
while getopts p:r: option; do
  case $option in
    p) processes=$OPTARG ;;
    r) reps=$OPTARG ;;
    *) echo "usage: sh bench/ratio.sh [-p PROCESSES] [-r REPS] [COMPILER...]" >&2; exit 2 ;;
  esac
done
shift $((OPTIND - 1))
[ $# -gt 0 ] || set -- g++ clang++-14 clang++-16
iecoop_require_packages cmake make g++ clang-14 clang-16 libbenchmark-dev valgrind

jobs=$(iecoop_jobs)
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT

for compiler in "$@"; do
  dir=build/ratio-$compiler
  echo "== ratio: building with $compiler in $dir" >&2
  cmake -S . -B "$dir" -DCMAKE_CXX_COMPILER="$compiler" -DCMAKE_BUILD_TYPE=Release -DIECOOP_BUILD_BENCH=ON \
    -DIECOOP_BUILD_TESTS=OFF -DIECOOP_BUILD_EXAMPLES=OFF -DIECOOP_BUILD_TOOLS=OFF -DIECOOP_BUILD_CHECK=OFF \
    -DIECOOP_INSTALL=OFF >/dev/null
  cmake --build "$dir" -j "$jobs" --target iecoop_workload_ratio iecoop_bench_count >/dev/null
done

# The processes, the compilers taking turns.
p=1
while [ "$p" -le "$processes" ]; do
  for compiler in "$@"; do
    echo "== ratio: process $p of $processes, $compiler" >&2
    "build/ratio-$compiler/bench/iecoop_workload_ratio" --reps "$reps" >>"$work/$compiler.runs"
  done
  p=$((p + 1))
done

# field <file> <n>: field n of every process's line ("ratio R p10 A p90 B iecoop_ns X twin_ns Y
# ..."), sorted.
field() {
  awk -v n="$2" '{ print $n }' "$1" | sort -g
}

# The median of sorted numbers (stdin).
median() {
  awk '{ v[NR] = $1 } END { if (NR % 2) print v[(NR + 1) / 2]; else print (v[NR / 2] + v[NR / 2 + 1]) / 2 }'
}

# The CPU the figures hold for (docs/performance.md keeps a history per CPU: a ratio must hold
# on each machine, and machines differ).
# A virtual machine may name only the brand ("AMD EPYC"): the family and model tell the
# generation (family 23: Zen 1/2, 25: Zen 3/4, 26: Zen 5).
cpu=$(LC_ALL=C lscpu 2>/dev/null | sed -n 's/^Model name: *//p' | head -n 1)
family=$(LC_ALL=C lscpu 2>/dev/null | sed -n 's/^CPU family: *//p' | head -n 1)
model=$(LC_ALL=C lscpu 2>/dev/null | sed -n 's/^Model: *//p' | head -n 1)
echo "CPU: ${cpu:-unknown} (family ${family:-?}, model ${model:-?}), $(nproc) cores;" \
  "$(date -u +%Y-%m-%d); $(git rev-parse --short HEAD 2>/dev/null || echo 'no git')"
echo
echo "| compiler | time, iecoop / twin: median of $processes processes (their range) | 10th–90th percentile of the repetitions | ns per scan, iecoop / twin | instructions per scan, iecoop / twin | instructions, iecoop / twin | instructions, iecoop / twin without stored inputs |"
echo "|---|---:|---:|---:|---:|---:|---:|"
for compiler in "$@"; do
  runs=$work/$compiler.runs
  ratio=$(field "$runs" 2 | median)
  low=$(field "$runs" 2 | head -n 1)
  high=$(field "$runs" 2 | tail -n 1)
  p10=$(field "$runs" 4 | median)
  p90=$(field "$runs" 6 | median)
  iecoop_ns=$(field "$runs" 8 | median)
  twin_ns=$(field "$runs" 10 | median)
  counts=$(sh bench/callgrind.sh "build/ratio-$compiler/bench/iecoop_bench_count" workload_iecoop workload_handwritten \
    workload_handwritten_minimal)
  iecoop_ins=$(echo "$counts" | awk '$1 == "workload_iecoop" { print $2 }')
  twin_ins=$(echo "$counts" | awk '$1 == "workload_handwritten" { print $2 }')
  minimal_ins=$(echo "$counts" | awk '$1 == "workload_handwritten_minimal" { print $2 }')
  version=$("$compiler" --version | head -n 1)
  awk -v c="$version" -v r="$ratio" -v lo="$low" -v hi="$high" -v p10="$p10" -v p90="$p90" -v a="$iecoop_ns" \
    -v b="$twin_ns" -v ia="$iecoop_ins" -v ib="$twin_ins" -v im="$minimal_ins" 'BEGIN {
      printf "| %s | %.3f (%.3f–%.3f) | %.3f–%.3f | %.0f / %.0f | %.0f / %.0f | %.3f | %.3f |\n",
        c, r, lo, hi, p10, p90, a, b, ia, ib, ia / ib, ia / im
    }'
done
