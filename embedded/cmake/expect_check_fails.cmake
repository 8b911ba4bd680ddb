# Proves that check_symbols.cmake can fail: runs it on a deliberately leaky image and passes
# only if the check fails and names the expected symbol.
#
#   cmake -DNM=<nm> -DELF=<leaky image> -DEXPECT=<regex> -P expect_check_fails.cmake
cmake_minimum_required(VERSION 3.25)
execute_process(
  COMMAND ${CMAKE_COMMAND} -DNM=${NM} -DELF=${ELF} -P ${CMAKE_CURRENT_LIST_DIR}/check_symbols.cmake
  OUTPUT_VARIABLE output
  ERROR_VARIABLE errors
  RESULT_VARIABLE status)
message("${output}${errors}")
if(status EQUAL 0)
  message(FATAL_ERROR "check_symbols.cmake passed ${ELF}, which links '${EXPECT}' on purpose")
endif()
if(NOT errors MATCHES "${EXPECT}")
  message(FATAL_ERROR "check_symbols.cmake failed on ${ELF}, but did not name '${EXPECT}'")
endif()
message("check_symbols.cmake rejects ${ELF} as it must")
