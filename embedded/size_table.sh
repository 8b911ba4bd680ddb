#!/bin/sh
# Builds the firmware examples for the six Cortex-M cores (the CMake presets) and writes
# their sizes into docs/embedded.md, between the size-table markers. Run it after a change
# that may change the sizes, and commit docs/embedded.md.
#
#   sh embedded/size_table.sh
#
# Needs the cross toolchain (see docs/embedded.md); it takes a few seconds.
set -eu
cd "$(dirname "$0")/.."
. tools/require_packages.sh
iecoop_require_packages cmake gcc-arm-none-eabi libnewlib-arm-none-eabi libstdc++-arm-none-eabi-dev qemu-system-arm

doc=docs/embedded.md
examples="i_math_interface property_and_method timers_counters scheduler trace sfc_station fault"
cores="cortex-m0plus cortex-m3 cortex-m4f cortex-m7 cortex-m33 cortex-m55"

for core in $cores; do
  cmake --preset "$core" >/dev/null
  cmake --build --preset "$core" >/dev/null
done

# One row per image, from the section sizes (`size -A`): text is everything the image keeps
# in flash but the first values of .data (vector table, code, constants, the constructor
# list), data is .data (in RAM, and its first values in flash), bss is .bss without the
# stack, which the linker script reserves apart, in .stack.
row() {
  arm-none-eabi-size -A -d "$2" | awk -v example="$1" -v core="$3" '
    $1 == ".vectors" || $1 == ".text" || $1 == ".ARM.exidx" || $1 == ".init_array" { text += $2 }
    $1 == ".data" { data = $2 }
    $1 == ".bss" { bss = $2 }
    $1 == ".stack" { stack = $2 }
    END { printf "| %s | %s | %d | %d | %d | %d | %d | %d |\n", example, core, text, data, bss, text + data, data + bss, stack }'
}

table=$(mktemp)
trap 'rm -f "$table"' EXIT
{
  echo "<!-- size-table begin: written by embedded/size_table.sh, do not edit -->"
  echo "| example | core | text | data | bss | flash (text + data) | RAM (data + bss) | stack reserved |"
  echo "|---|---|--:|--:|--:|--:|--:|--:|"
  for example in $examples; do
    for core in $cores; do
      row "$example" "build/$core/embedded/fw_$example.elf" "$core"
    done
  done
  echo
  echo "Bytes; $(arm-none-eabi-gcc --version | head -n 1), \`-Os\` (MinSizeRel), newlib-nano."
  # The target: interface + timers + scheduler in 16 KiB of flash and 2 KiB of RAM on an M3.
  row scheduler build/cortex-m3/embedded/fw_scheduler.elf cortex-m3 | awk -F'|' '{
    flash = $7 + 0; ram = $8 + 0
    printf "\nThe target, interface + timers + scheduler in 16 KiB of flash and 2 KiB of RAM on a Cortex-M3: `scheduler` takes %d of 16384 bytes of flash (%s) and %d of 2048 bytes of RAM (%s).\n",
      flash, flash <= 16384 ? "met" : "MISSED", ram, ram <= 2048 ? "met" : "MISSED" }'
  echo "<!-- size-table end -->"
} > "$table"

# Replace what lies between the markers (inclusive) with the new table.
awk -v table="$table" '
  /^<!-- size-table begin/ { while ((getline line < table) > 0) print line; skipping = 1; next }
  /^<!-- size-table end/ { skipping = 0; next }
  !skipping { print }' "$doc" > "$doc.new"
mv "$doc.new" "$doc"
echo "iecoop: wrote the size table into $doc"
