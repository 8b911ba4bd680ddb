#!/bin/sh
# Counts the instructions one scan of the timers_counters and sfc_station examples executes on
# each of the six Cortex-M cores, under QEMU's -icount (embedded/scan_cost.hpp says how), and
# writes the table into docs/embedded.md, between the scan-cost markers. Run it after a change
# that may change the cost, and commit docs/embedded.md.
#
#   sh embedded/scan_cost_table.sh
#
# Builds each core's preset once more in build/<core>-scan-cost (with IECOOP_FIRMWARE_SCAN_COST),
# only these two images; takes under a minute.
set -eu
cd "$(dirname "$0")/.."
. tools/require_packages.sh
iecoop_require_packages cmake gcc-arm-none-eabi libnewlib-arm-none-eabi libstdc++-arm-none-eabi-dev qemu-system-arm

doc=docs/embedded.md
. embedded/cores.sh
cores=$iecoop_cores
examples="timers_counters sfc_station"
results=$(mktemp)
table=$(mktemp)
trap 'rm -f "$results" "$table"' EXIT

for core in $cores; do
  dir=build/$core-scan-cost
  cmake --preset "$core" -B "$dir" -DIECOOP_FIRMWARE_SCAN_COST=ON >/dev/null
  machine=$(iecoop_machine_of "$core")
  for example in $examples; do
    cmake --build "$dir" --target "fw_$example" >/dev/null
    # shift=0: one instruction is one nanosecond of the virtual clock the SysTick counts.
    line=$(timeout 120 qemu-system-arm -M "$machine" -icount shift=0 -display none -monitor none -serial none \
      -semihosting-config enable=on,target=native -kernel "$dir/embedded/fw_$example.elf" | grep "^scan cost ")
    [ -n "$line" ] || { echo "scan_cost_table.sh: $example on $core printed no count" >&2; exit 1; }
    count=$(echo "$line" | sed 's/^scan cost [a-z_]*: \([0-9.]*\) instructions.*/\1/')
    echo "$core $machine $example $count" >>"$results"
  done
done

{
  echo "<!-- scan-cost begin: written by embedded/scan_cost_table.sh, do not edit -->"
  echo "| core | QEMU board | timers_counters: instructions per scan | sfc_station: instructions per scan |"
  echo "|---|---|--:|--:|"
  for core in $cores; do
    awk -v core="$core" '$1 == core { machine = $2; count[$3] = $4 }
      END { printf "| %s | %s | %s | %s |\n", core, machine, count["timers_counters"], count["sfc_station"] }' "$results"
  done
  echo
  echo "Averages over every scan of the example (151 and 601 scans); $(arm-none-eabi-gcc --version | head -n 1), \`-Os -flto\`; $(qemu-system-arm --version | head -n 1)."
  echo "<!-- scan-cost end -->"
} >"$table"

awk -v table="$table" '
  /^<!-- scan-cost begin/ { while ((getline line < table) > 0) print line; skipping = 1; next }
  /^<!-- scan-cost end/ { skipping = 0; next }
  !skipping { print }
' "$doc" >"$doc.new"
grep -q "scan-cost begin" "$doc.new" || { rm -f "$doc.new"; echo "scan_cost_table.sh: no scan-cost markers in $doc" >&2; exit 1; }
mv "$doc.new" "$doc"
echo "iecoop: wrote the scan cost table into $doc"
