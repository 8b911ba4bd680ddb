#!/bin/sh
# More random charts for the SFC engines' differential test than CI runs (tests/CMakeLists.txt,
# sfc.engines_agree_on_random_charts): COUNT charts from SEED, in files of 4 compiled side by
# side, each chart run on the compiled and the general engine in both scan orders for SCANS scans.
#
#   sh tests/sfc_engines/run_many.sh [SEED [COUNT [SCANS]]]     (defaults: 1 200 5000)
#
# Needs g++, python3, doctest and fmt (as the test suite). Prints each file's result; exits 1 if
# any chart differs, naming it, its order and the first scan that differs.
set -eu
cd "$(dirname "$0")/../.."
seed=${1:-1}
count=${2:-200}
scans=${3:-5000}
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
jobs=$(nproc)
flags="-std=c++20 -O1 -Iinclude -Itests/support -Itests/sfc_engines"
g++ $flags -c tests/support/main.cpp -o "$work/main.o"
n=0
first=0
while [ "$first" -lt "$count" ]; do
  batch=4
  [ $((first + batch)) -le "$count" ] || batch=$((count - first))
  python3 tests/sfc_engines/generate_charts.py --seed "$seed" --first "$first" --count "$batch" --scans "$scans" \
    --out "$work/charts_$n.cpp"
  first=$((first + batch))
  n=$((n + 1))
done
# compile the files, $jobs at a time
ls "$work"/charts_*.cpp | xargs -P "$jobs" -I{} sh -c 'g++ '"$flags"' -c "$1" -o "$1.o"' _ {}
failed=0
for o in "$work"/charts_*.cpp.o; do
  g++ "$o" "$work/main.o" -o "$work/run" -lfmt
  if ! "$work/run" > "$work/out.txt" 2>&1; then
    failed=1
    cat "$work/out.txt"
  else
    grep -o '[0-9]* charts ([0-9]* on the compiled engine), [0-9]* scans on each engine' "$work/out.txt" || true
  fi
done
[ "$failed" -eq 0 ] && echo "run_many: seed $seed, $count charts, $scans scans each: the engines agree"
exit "$failed"
