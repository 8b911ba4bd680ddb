#!/bin/sh
# A long fuzz run of iecoop's libFuzzer targets (tests/fuzz/; docs/reliability.md):
#   sh tools/fuzz.sh [SECONDS] [TARGET...]
# builds the targets with clang++ (build/fuzz), then fuzzes each for SECONDS (default 600), one
# after the other (one core), and prints per target: executions, executions per second,
# coverage (libFuzzer's cov: edges and ft: features at the end), corpus size and findings.
# Each target keeps its corpus across runs in $IECOOP_FUZZ_DIR/<target>/corpus (default
# build/fuzz-run; never the source tree; seeded from tests/fuzz/corpus/<target>/), its findings
# in .../artifacts/ and libFuzzer's log of the last run in .../fuzz.log. Run it under
# `nice -n 19` on a shared machine. Exit status 1 if anything was found.
set -eu
cd "$(dirname "$0")/.."
. tools/require_packages.sh
iecoop_require_packages cmake make clang libclang-rt-14-dev doctest-dev libfmt-dev

seconds=${1:-600}
[ $# -gt 0 ] && shift
case $seconds in '' | *[!0-9]*)
  echo "usage: sh tools/fuzz.sh [SECONDS] [TARGET...]" >&2
  exit 2
  ;;
esac
work=${IECOOP_FUZZ_DIR:-build/fuzz-run}
build=build/fuzz

echo "== iecoop: building the fuzz targets (clang++, $build)"
cmake -S . -B "$build" -DCMAKE_CXX_COMPILER=clang++ -DCMAKE_BUILD_TYPE=Release -DIECOOP_WERROR=ON \
  -DIECOOP_BUILD_TESTS=ON -DIECOOP_BUILD_FUZZ=ON -DIECOOP_BUILD_EXAMPLES=OFF -DIECOOP_BUILD_BENCH=OFF \
  -DIECOOP_BUILD_TOOLS=OFF -DIECOOP_BUILD_CHECK=OFF >/dev/null
list=$build/tests/fuzz/targets.txt
targets=${*:-$(cut -d' ' -f1 "$list")}
for target in $targets; do
  grep -q "^$target " "$list" || { echo "iecoop: no fuzz target $target; there are: $(cut -d' ' -f1 "$list" | tr '\n' ' ')" >&2; exit 2; }
  cmake --build "$build" -j "${IECOOP_FUZZ_JOBS:-2}" --target "iecoop_fuzz_$target" >/dev/null
done

found=0
report=$work/report.txt
mkdir -p "$work"
{
  echo "iecoop fuzz run, $(date -u '+%Y-%m-%d %H:%M UTC'), $(clang++ --version | head -n 1), ${seconds} s per target"
  printf '%-16s %8s %12s %8s %6s %7s %7s  %s\n' target seconds executions exec/s cov ft corpus findings
} >"$report"
cat "$report"
for target in $targets; do
  line=$(grep "^$target " "$list")
  max_len=$(echo "$line" | cut -d' ' -f2)
  dict=$(echo "$line" | cut -d' ' -f3)
  dir=$work/$target
  mkdir -p "$dir/corpus" "$dir/artifacts"
  cp -p tests/fuzz/corpus/"$target"/* "$dir/corpus/" 2>/dev/null || true
  before=$(ls "$dir/artifacts" | wc -l)
  set -- -max_total_time="$seconds" -max_len="$max_len" -timeout=10 -rss_limit_mb=2048 -print_final_stats=1 \
    -artifact_prefix="$dir/artifacts/"
  [ -n "$dict" ] && set -- "$@" -dict="$dict"
  start=$(date +%s)
  status=0
  "$build/tests/fuzz/iecoop_fuzz_$target" "$@" "$dir/corpus" >"$dir/fuzz.log" 2>&1 || status=$?
  elapsed=$(($(date +%s) - start))
  runs=$(sed -n 's/^stat::number_of_executed_units: *//p' "$dir/fuzz.log")
  speed=$(sed -n 's/^stat::average_exec_per_sec: *//p' "$dir/fuzz.log")
  last=$(grep -o 'cov: [0-9]* ft: [0-9]*' "$dir/fuzz.log" | tail -n 1)
  cov=$(echo "$last" | cut -d' ' -f2)
  ft=$(echo "$last" | cut -d' ' -f4)
  corpus=$(ls "$dir/corpus" | wc -l)
  findings=$(($(ls "$dir/artifacts" | wc -l) - before))
  if [ "$status" -ne 0 ] && [ "$findings" -eq 0 ]; then findings=1; fi  # a failure that left no input
  note=""
  if [ "$findings" -gt 0 ]; then
    found=1
    note="  $(grep -m 1 -E 'iecoop fuzz: property broken|ERROR: |runtime error|deadly signal' "$dir/fuzz.log" || true) (see $dir/fuzz.log)"
  fi
  printf '%-16s %8s %12s %8s %6s %7s %7s  %s%s\n' "$target" "$elapsed" "${runs:-?}" "${speed:-?}" "${cov:-?}" \
    "${ft:-?}" "$corpus" "$findings" "$note" | tee -a "$report"
done
echo "== iecoop: report in $report"
exit "$found"
