#!/bin/sh
# Instruction counts per iteration of each benchmark kernel, measured with
# valgrind --tool=callgrind (stable where timings on a shared machine are not):
#
#   sh bench/callgrind.sh <path/to/iecoop_bench_count> [kernel...]
#
# Each kernel runs twice, n1 and n2 iterations; (count(n2) - count(n1)) / (n2 - n1) is the
# count per iteration without the program's start-up. Prints "kernel instructions" lines.
set -eu
count_tool=$1
shift
[ $# -gt 0 ] || set -- $("$count_tool" --list)

collected() {
  valgrind --tool=callgrind --callgrind-out-file=/dev/null "$count_tool" "$1" "$2" 2>&1 |
    sed -n 's/.*Collected : *\([0-9][0-9]*\).*/\1/p'
}

for kernel in "$@"; do
  case $kernel in
    workload_*) n1=20 n2=120 ;;
    task_cycle_*) n1=2000 n2=12000 ;;
    sfc_*) n1=10000 n2=110000 ;;
    *) n1=100000 n2=1100000 ;;
  esac
  a=$(collected "$kernel" $n1)
  b=$(collected "$kernel" $n2)
  [ -n "$a" ] && [ -n "$b" ] || { echo "callgrind.sh: no count for $kernel" >&2; exit 1; }
  awk -v k="$kernel" -v a="$a" -v b="$b" -v n1=$n1 -v n2=$n2 'BEGIN { printf "%s %.1f\n", k, (b - a) / (n2 - n1) }'
done
