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
iecoop_require_packages cmake python3 gcc-arm-none-eabi libnewlib-arm-none-eabi libstdc++-arm-none-eabi-dev qemu-system-arm

doc=docs/embedded.md
examples="i_math_interface property_and_method timers_counters scheduler trace sfc_station process_image pid_loop fault"
. embedded/cores.sh
cores=$iecoop_cores

for core in $cores; do
  cmake --preset "$core" >/dev/null
  cmake --build --preset "$core" >/dev/null
  # The same images, painting the stack and reporting its high-water mark (not counted above).
  cmake --preset "$core" -B "build/$core-stack" -DIECOOP_FIRMWARE_STACK_REPORT=ON >/dev/null
  for example in $examples; do cmake --build "build/$core-stack" --target "fw_$example" >/dev/null; done
done

# One row per image, from the section sizes (`size -A`): text is everything the image keeps
# in flash but the first values of .data (vector table, code, constants, the constructor
# list), data is .data (in RAM, and its first values in flash), bss is .bss without the
# stack, which the linker script reserves apart, in .stack. Then the stack: the deepest chain
# of direct calls from GCC's call graphs (embedded/stack_depth.py; "+" where calls through
# pointers were not followed) and the high-water mark the same image reports when built with
# IECOOP_FIRMWARE_STACK_REPORT (in build/<core>-stack) and run under QEMU (exit_status.hpp).
row() {
  build=build/$3/embedded
  # The call graphs: the link's where it optimised at link time, else each object's.
  graphs=$(find "$build/CMakeFiles/fw_$1.dir" -maxdepth 1 -name '*.ltrans.ci')
  [ -n "$graphs" ] || graphs=$(find "$build/CMakeFiles/fw_$1.dir" "$build/CMakeFiles/iecoop_firmware_startup.dir" -name '*.cpp.ci')
  # shellcheck disable=SC2086 # the file names have no spaces
  static=$(python3 embedded/stack_depth.py $graphs |
    sed -n 's/^static stack: \([0-9]*\) bytes.*indirect calls not followed.*/\1+/p; s/^static stack: \([0-9]*\) bytes.*/\1/p' | head -n 1)
  measured=$(timeout 60 qemu-system-arm -M "$(iecoop_machine_of "$3")" -display none -monitor none -serial none \
    -semihosting-config enable=on,target=native -kernel "build/$3-stack/embedded/fw_$1.elf" 2>&1 >/dev/null | sed -n 's/^stack high-water: \([0-9]*\) bytes.*/\1/p')
  arm-none-eabi-size -A -d "$2" | awk -v example="$1" -v core="$3" -v static="$static" -v measured="$measured" '
    $1 == ".vectors" || $1 == ".text" || $1 == ".ARM.exidx" || $1 == ".init_array" { text += $2 }
    $1 == ".data" { data = $2 }
    $1 == ".bss" { bss = $2 }
    $1 == ".stack" { stack = $2 }
    END { printf "| %s | %s | %d | %d | %d | %d | %d | %s | %s | %d |\n", example, core, text, data, bss, text + data, data + bss, static, measured, stack }'
}

table=$(mktemp)
trap 'rm -f "$table"' EXIT
{
  echo "<!-- size-table begin: written by embedded/size_table.sh, do not edit -->"
  echo "| example | core | text | data | bss | flash (text + data) | RAM (data + bss) | stack: direct calls | stack: high-water | stack reserved |"
  echo "|---|---|--:|--:|--:|--:|--:|--:|--:|--:|"
  for example in $examples; do
    for core in $cores; do
      row "$example" "build/$core/embedded/fw_$example.elf" "$core"
    done
  done
  echo
  echo "Bytes; $(arm-none-eabi-gcc --version | head -n 1), \`-Os\` (MinSizeRel) and \`-flto\`, newlib-nano."
  # The target (issue 39): the scheduler example in 8 KiB of flash and 1 KiB of RAM on an M3.
  row scheduler build/cortex-m3/embedded/fw_scheduler.elf cortex-m3 | awk -F'|' '{
    flash = $7 + 0; ram = $8 + 0
    printf "\nThe target, the scheduler example in 8 KiB of flash and 1 KiB of RAM on a Cortex-M3: `scheduler` takes %d of 8192 bytes of flash (%s) and %d of 1024 bytes of RAM (%s).\n",
      flash, flash <= 8192 ? "met" : "MISSED", ram, ram <= 1024 ? "met" : "MISSED" }'
  echo "<!-- size-table end -->"
} > "$table"

# Replace what lies between the markers (inclusive) with the new table.
awk -v table="$table" '
  /^<!-- size-table begin/ { while ((getline line < table) > 0) print line; skipping = 1; next }
  /^<!-- size-table end/ { skipping = 0; next }
  !skipping { print }' "$doc" > "$doc.new"
mv "$doc.new" "$doc"
echo "iecoop: wrote the size table into $doc"
