# CMake toolchain file: iecoop firmware for ARM Cortex-M, built with Debian's arm-none-eabi
# GCC and newlib-nano, no operating system.
#
#   cmake -S . -B build/cortex-m3 --toolchain embedded/cmake/arm-none-eabi.cmake \
#         -DIECOOP_CORTEX_M=cortex-m3 -DIECOOP_BUILD_FIRMWARE=ON
#
# (or simply `cmake --preset cortex-m3`). IECOOP_CORTEX_M picks the core, and with it the
# flags and the QEMU board the firmware runs on (a board that has that core, or for the
# Cortex-M0+ the nearest QEMU has, the micro:bit's Cortex-M0, whose instruction set is the same
# ARMv6-M):
#
#   cortex-m0plus  ARMv6-M, no FPU, no divide instruction, no unaligned access   microbit
#   cortex-m3      ARMv7-M, no FPU (soft float)                                  mps2-an385
#   cortex-m4f     ARMv7E-M, single-precision FPU, hard-float ABI                mps2-an386
#   cortex-m7      ARMv7E-M, double-precision FPU, hard-float ABI                mps2-an500
#   cortex-m33     ARMv8-M Mainline, TrustZone, single-precision FPU, hard-float mps2-an505
#   cortex-m55     ARMv8.1-M Mainline, Helium (MVE), FPU, hard-float              mps3-an547
#
# The flags below are the whole contract with the firmware: C++20 at -Os, no exceptions, no
# RTTI, no thread-safe statics, one section per function and object so the linker can drop
# what is unused.
set(CMAKE_SYSTEM_NAME Generic)  # bare metal: no shared libraries, no rpath, CMAKE_CROSSCOMPILING
set(CMAKE_SYSTEM_PROCESSOR arm)

set(IECOOP_CORTEX_M_CORES cortex-m0plus cortex-m3 cortex-m4f cortex-m7 cortex-m33 cortex-m55)
set(IECOOP_CORTEX_M "cortex-m3" CACHE STRING "The Cortex-M core to build for: ${IECOOP_CORTEX_M_CORES}")
set_property(CACHE IECOOP_CORTEX_M PROPERTY STRINGS ${IECOOP_CORTEX_M_CORES})
if(IECOOP_CORTEX_M STREQUAL "cortex-m0plus")
  set(_iecoop_cpu "-mcpu=cortex-m0plus -mthumb")
  set(IECOOP_QEMU_MACHINE microbit)
elseif(IECOOP_CORTEX_M STREQUAL "cortex-m3")
  set(_iecoop_cpu "-mcpu=cortex-m3 -mthumb")
  set(IECOOP_QEMU_MACHINE mps2-an385)
elseif(IECOOP_CORTEX_M STREQUAL "cortex-m4f")
  set(_iecoop_cpu "-mcpu=cortex-m4 -mthumb -mfpu=fpv4-sp-d16 -mfloat-abi=hard")
  set(IECOOP_QEMU_MACHINE mps2-an386)
elseif(IECOOP_CORTEX_M STREQUAL "cortex-m7")
  set(_iecoop_cpu "-mcpu=cortex-m7 -mthumb -mfpu=fpv5-d16 -mfloat-abi=hard")
  set(IECOOP_QEMU_MACHINE mps2-an500)
elseif(IECOOP_CORTEX_M STREQUAL "cortex-m33")
  set(_iecoop_cpu "-mcpu=cortex-m33 -mthumb -mfpu=fpv5-sp-d16 -mfloat-abi=hard")
  set(IECOOP_QEMU_MACHINE mps2-an505)
elseif(IECOOP_CORTEX_M STREQUAL "cortex-m55")
  set(_iecoop_cpu "-mcpu=cortex-m55 -mthumb -mfloat-abi=hard")
  set(IECOOP_QEMU_MACHINE mps3-an547)
else()
  string(REPLACE ";" ", " _iecoop_cores "${IECOOP_CORTEX_M_CORES}")
  message(FATAL_ERROR "iecoop: IECOOP_CORTEX_M is '${IECOOP_CORTEX_M}'; use one of ${_iecoop_cores}")
endif()
# The board's memory (embedded/boards/<board>/memory.ld, included by embedded/cortex-m.ld).
set(IECOOP_BOARD_DIR "${CMAKE_CURRENT_LIST_DIR}/../boards/${IECOOP_QEMU_MACHINE}")
cmake_path(NORMAL_PATH IECOOP_BOARD_DIR)

set(CMAKE_C_COMPILER arm-none-eabi-gcc)
set(CMAKE_CXX_COMPILER arm-none-eabi-g++)
find_program(IECOOP_ARM_SIZE arm-none-eabi-size REQUIRED)

# The compiler checks would link a program without our start-up code and linker script,
# which cannot work on bare metal: let them build a static library instead.
set(CMAKE_TRY_COMPILE_TARGET_TYPE STATIC_LIBRARY)

# CMake passes CMAKE_<LANG>_FLAGS to the link as well, which is where the core flags must
# also be: they choose the multilib (Thumb, v7-M, FPU) of libgcc and newlib. nano.specs is
# therefore given here only; a second copy on the linker flags is a fatal GCC error.
# On the compile line it selects newlib-nano's configuration headers, on the link line its
# libraries.
set(_iecoop_common "${_iecoop_cpu} --specs=nano.specs -ffunction-sections -fdata-sections")
set(CMAKE_C_FLAGS_INIT "${_iecoop_common}")
set(CMAKE_CXX_FLAGS_INIT "${_iecoop_common} -fno-exceptions -fno-rtti -fno-threadsafe-statics")
# No crt0: the firmware's own reset handler (embedded/startup.cpp) starts it. No nosys.specs or
# rdimon.specs either, so nothing provides _sbrk: a heap cannot be linked by accident.
set(CMAKE_EXE_LINKER_FLAGS_INIT "-nostartfiles -Wl,--gc-sections")
set(CMAKE_EXECUTABLE_SUFFIX_C .elf)
set(CMAKE_EXECUTABLE_SUFFIX_CXX .elf)

# The binutils the tests and embedded/size_table.sh use on the images.
find_program(IECOOP_ARM_NM arm-none-eabi-nm REQUIRED)
find_program(IECOOP_ARM_OBJDUMP arm-none-eabi-objdump REQUIRED)
