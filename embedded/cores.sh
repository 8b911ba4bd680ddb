# Sourced by embedded/size_table.sh and embedded/scan_cost_table.sh: the Cortex-M cores iecoop
# builds firmware for (the CMake presets) and the QEMU board of each, as
# embedded/cmake/arm-none-eabi.cmake chooses them.
# shellcheck shell=sh

iecoop_cores="cortex-m0plus cortex-m3 cortex-m4f cortex-m7 cortex-m33 cortex-m55"

# iecoop_machine_of <core>: the QEMU board that runs the core's images.
iecoop_machine_of() {
  case $1 in
    cortex-m0plus) echo microbit ;;
    cortex-m3) echo mps2-an385 ;;
    cortex-m4f) echo mps2-an386 ;;
    cortex-m7) echo mps2-an500 ;;
    cortex-m33) echo mps2-an505 ;;
    cortex-m55) echo mps3-an547 ;;
    *) echo "iecoop: no QEMU board for core '$1'" >&2; return 1 ;;
  esac
}
