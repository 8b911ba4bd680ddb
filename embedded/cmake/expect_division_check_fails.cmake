# Proves that check_divisions.cmake can fail: runs it on an image that divides 64-bit integers
# in a function of its own (embedded/leaky/leaky.cpp, LEAKY_DIVISION) and passes only if the
# check fails and names that function.
#
#   cmake -DOBJDUMP=<objdump> -DELF=<leaky image> -P expect_division_check_fails.cmake
cmake_minimum_required(VERSION 3.25)
execute_process(
  COMMAND ${CMAKE_COMMAND} -DOBJDUMP=${OBJDUMP} -DELF=${ELF} -P ${CMAKE_CURRENT_LIST_DIR}/check_divisions.cmake
  OUTPUT_VARIABLE output
  ERROR_VARIABLE errors
  RESULT_VARIABLE status)
message("${output}${errors}")
if(status EQUAL 0)
  message(FATAL_ERROR "check_divisions.cmake passed ${ELF}, which divides 64-bit integers on purpose")
endif()
if(NOT errors MATCHES "cycle_body[^\n]* calls __aeabi_uldivmod")
  message(FATAL_ERROR "check_divisions.cmake failed on ${ELF}, but did not name cycle_body and __aeabi_uldivmod")
endif()
message("check_divisions.cmake rejects ${ELF} as it must")
