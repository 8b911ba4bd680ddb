# iecoop's firmware functions, for iecoop's own firmware (embedded/CMakeLists.txt) and for a
# user's project (docs/embedded.md, "Your own firmware project"): find_package(iecoop) and
# add_subdirectory(iecoop) both provide them. The project is configured with iecoop's toolchain
# file, which chooses the core and its QEMU board:
#
#   cmake -S . -B build --toolchain <iecoop>/embedded/cmake/arm-none-eabi.cmake -DIECOOP_CORTEX_M=cortex-m0plus
#   (installed: <prefix>/share/cmake/iecoop/firmware/cmake/arm-none-eabi.cmake)
#
# iecoop_add_firmware(<target> <source>... [MEMORY <directory>])
#   (in a project with C and C++ enabled: project(<name> LANGUAGES C CXX))
#   A firmware image, <target>.elf, for the core of the toolchain file, optimised at link time
#   (unless CMAKE_INTERPROCEDURAL_OPTIMIZATION says otherwise): the sources, iecoop's
#   start-up code (vector table, reset handler, fault handlers), iecoop's linker script (the
#   vector table first, the stack apart, no heap) with the memory of the core's QEMU board, or
#   with the memory.ld in MEMORY <directory> (your part's flash and RAM: copy a board's and
#   change ORIGIN and LENGTH), and a map file. It links iecoop::iecoop, defines IECOOP_NO_STDIO
#   and can include the firmware's helpers: "tick.hpp" (the SysTick), "console.hpp" and
#   "semihosting.hpp" (text to a debugger), "fault_handler.hpp", "exit_status.hpp".
#
# iecoop_add_firmware_test(<name> <target> EXPECTED <file> [STATUS <status>])
#   A CTest test that runs the image under qemu-system-arm on the core's board, with
#   semihosting, and passes if it ends with STATUS (0 if not given) and printed exactly the
#   contents of EXPECTED.
include_guard(GLOBAL)

# IECOOP_FIRMWARE_DIR, in each function: the firmware's directory, embedded/ in the source tree,
# firmware/ in the installed package (found from this file, whichever directory scope calls).
function(iecoop_add_firmware target)
  get_filename_component(IECOOP_FIRMWARE_DIR "${CMAKE_CURRENT_FUNCTION_LIST_DIR}/.." ABSOLUTE)
  cmake_parse_arguments(PARSE_ARGV 1 arg "" "MEMORY" "")
  if(NOT CMAKE_CROSSCOMPILING)
    message(FATAL_ERROR "iecoop: iecoop_add_firmware(${target}) builds for a Cortex-M; configure the project with "
                        "--toolchain ${IECOOP_FIRMWARE_DIR}/cmake/arm-none-eabi.cmake -DIECOOP_CORTEX_M=<core>")
  endif()
  set(memory "${arg_MEMORY}")
  if(NOT memory)
    if(NOT DEFINED IECOOP_BOARD_DIR)
      message(FATAL_ERROR "iecoop: iecoop_add_firmware(${target}) needs the memory of the part: give MEMORY <directory> "
                          "with a memory.ld, or configure with iecoop's toolchain file, which names a QEMU board's")
    endif()
    set(memory "${IECOOP_BOARD_DIR}")
  endif()
  if(NOT EXISTS "${memory}/memory.ld")
    message(FATAL_ERROR "iecoop: iecoop_add_firmware(${target}): ${memory}/memory.ld does not exist")
  endif()
  # The image is linked by the C driver (see below), so the project enables C as well as C++.
  get_property(languages GLOBAL PROPERTY ENABLED_LANGUAGES)
  if(NOT "C" IN_LIST languages)
    message(FATAL_ERROR "iecoop: iecoop_add_firmware(${target}) links with arm-none-eabi-gcc: enable C in the project, "
                        "project(<name> LANGUAGES C CXX)")
  endif()
  # The start-up code, once per project.
  if(NOT TARGET iecoop_firmware_startup)
    add_library(iecoop_firmware_startup OBJECT ${IECOOP_FIRMWARE_DIR}/startup.cpp)
    target_link_libraries(iecoop_firmware_startup PRIVATE iecoop::iecoop)
    target_compile_definitions(iecoop_firmware_startup PRIVATE IECOOP_NO_STDIO)
    target_compile_options(iecoop_firmware_startup PRIVATE -Wno-psabi)
  endif()
  add_executable(${target} ${arg_UNPARSED_ARGUMENTS} $<TARGET_OBJECTS:iecoop_firmware_startup>)
  # Link-time optimisation (-flto), unless the project chose with CMAKE_INTERPROCEDURAL_OPTIMIZATION:
  # the whole image optimised as one, 10 % smaller (docs/embedded.md, "Sizes").
  if(NOT DEFINED CMAKE_INTERPROCEDURAL_OPTIMIZATION)
    set_property(TARGET ${target} iecoop_firmware_startup PROPERTY INTERPROCEDURAL_OPTIMIZATION ON)
  endif()
  target_link_libraries(${target} PRIVATE iecoop::iecoop)
  target_include_directories(${target} PRIVATE ${IECOOP_FIRMWARE_DIR})
  # No <cstdio> in iecoop's default fault handler (include/iecoop/fault.hpp). GCC's note that
  # passing some small structs (TIME, for one) changed ABI in GCC 7.1 only matters when linking
  # code built by an older GCC.
  target_compile_definitions(${target} PRIVATE IECOOP_NO_STDIO)
  target_compile_options(${target} PRIVATE -Wno-psabi)
  set(script ${IECOOP_FIRMWARE_DIR}/cortex-m.ld)
  target_link_options(${target} PRIVATE -L${memory} -T${script} -Wl,-Map=$<TARGET_FILE:${target}>.map)
  # Linked by arm-none-eabi-gcc, not g++: g++ would add -lstdc++, which the slim package set
  # does not have and which nothing here needs (docs/embedded.md, "The toolchain").
  set_target_properties(${target} PROPERTIES LINKER_LANGUAGE C LINK_DEPENDS "${script};${memory}/memory.ld")
endfunction()

function(iecoop_add_firmware_test name target)
  get_filename_component(IECOOP_FIRMWARE_DIR "${CMAKE_CURRENT_FUNCTION_LIST_DIR}/.." ABSOLUTE)
  cmake_parse_arguments(PARSE_ARGV 2 arg "" "EXPECTED;STATUS" "")
  if(NOT arg_EXPECTED)
    message(FATAL_ERROR "iecoop: iecoop_add_firmware_test(${name}) needs EXPECTED <file>, the exact output")
  endif()
  if(NOT DEFINED arg_STATUS)
    set(arg_STATUS 0)
  endif()
  find_program(IECOOP_QEMU qemu-system-arm REQUIRED)
  get_filename_component(expected "${arg_EXPECTED}" ABSOLUTE)
  add_test(NAME ${name}
    COMMAND ${CMAKE_COMMAND} -DQEMU=${IECOOP_QEMU} -DMACHINE=${IECOOP_QEMU_MACHINE} -DELF=$<TARGET_FILE:${target}>
            -DEXPECTED=${expected} -DSTATUS=${arg_STATUS} -P ${IECOOP_FIRMWARE_DIR}/cmake/run_firmware.cmake)
  set_tests_properties(${name} PROPERTIES TIMEOUT 60)
endfunction()
