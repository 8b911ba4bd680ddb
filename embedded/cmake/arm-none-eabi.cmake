# CMake toolchain file: iecoop firmware for ARM Cortex-M, built with Debian's arm-none-eabi
# GCC and newlib-nano, no operating system.
#
#   cmake -S . -B build/cortex-m3 --toolchain embedded/cmake/arm-none-eabi.cmake \
#         -DIECOOP_CORTEX_M=cortex-m3 -DIECOOP_BUILD_FIRMWARE=ON
#
# (or simply `cmake --preset cortex-m3`). IECOOP_CORTEX_M picks the core: cortex-m3 (no FPU,
# soft float) or cortex-m4f (single-precision FPU, hard-float ABI). The flags below are the
# whole contract with the firmware: C++20 at -Os, no exceptions, no RTTI, no thread-safe
# statics, one section per function and object so the linker can drop what is unused.
set(CMAKE_SYSTEM_NAME Generic)  # bare metal: no shared libraries, no rpath, CMAKE_CROSSCOMPILING
set(CMAKE_SYSTEM_PROCESSOR arm)

set(IECOOP_CORTEX_M "cortex-m3" CACHE STRING "The Cortex-M core to build for: cortex-m3 or cortex-m4f")
set_property(CACHE IECOOP_CORTEX_M PROPERTY STRINGS cortex-m3 cortex-m4f)
if(IECOOP_CORTEX_M STREQUAL "cortex-m3")
  set(_iecoop_cpu "-mcpu=cortex-m3 -mthumb")
elseif(IECOOP_CORTEX_M STREQUAL "cortex-m4f")
  set(_iecoop_cpu "-mcpu=cortex-m4 -mthumb -mfpu=fpv4-sp-d16 -mfloat-abi=hard")
else()
  message(FATAL_ERROR "iecoop: IECOOP_CORTEX_M is '${IECOOP_CORTEX_M}'; use cortex-m3 or cortex-m4f")
endif()

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

# The QEMU board that has this core: ARM's MPS2 FPGA images AN385 (Cortex-M3) and AN386
# (Cortex-M4 with FPU). embedded/CMakeLists.txt runs the firmware on it.
if(IECOOP_CORTEX_M STREQUAL "cortex-m3")
  set(IECOOP_QEMU_MACHINE mps2-an385)
else()
  set(IECOOP_QEMU_MACHINE mps2-an386)
endif()

# The binutils the tests and embedded/size_table.sh use on the images.
find_program(IECOOP_ARM_NM arm-none-eabi-nm REQUIRED)
