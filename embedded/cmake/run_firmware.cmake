# Runs one firmware example and checks both what it printed and how it ended:
#
#   cmake -DELF=<image> -DEXPECTED=<file> [-DSTATUS=<exit status, 0 if not given>]
#         [-DQEMU=<qemu-system-arm> -DMACHINE=<board>] [-DTIMEOUT=<seconds>] -P run_firmware.cmake
#
# With QEMU, the image runs on the board with semihosting (its text arrives on stdout, its
# exit status becomes QEMU's); without, ELF is a host executable (the host twin of the same
# example). The test passes only if the status is STATUS and stdout is exactly the expected
# file. Both checks matter: a ctest PASS_REGULAR_EXPRESSION alone would accept a firmware that
# printed the right line and then crashed.
cmake_minimum_required(VERSION 3.25)
if(NOT DEFINED ELF OR NOT DEFINED EXPECTED)
  message(FATAL_ERROR "usage: cmake -DELF=<image> -DEXPECTED=<file> [-DQEMU=... -DMACHINE=...] -P run_firmware.cmake")
endif()
if(NOT DEFINED TIMEOUT)
  set(TIMEOUT 30)
endif()
if(NOT DEFINED STATUS)
  set(STATUS 0)
endif()

include(${CMAKE_CURRENT_LIST_DIR}/firmware_command.cmake)  # runs ELF: output, errors, status
file(READ ${EXPECTED} expected)

message("${output}")
if(errors)
  message("(stderr)\n${errors}")
endif()
set(failures "")
if(NOT status STREQUAL STATUS)
  string(APPEND failures "exit status '${status}', expected ${STATUS}\n")
endif()
if(NOT output STREQUAL expected)
  string(APPEND failures "the output differs from ${EXPECTED}, which reads:\n${expected}")
endif()
if(failures)
  message(FATAL_ERROR "${failures}")
endif()
