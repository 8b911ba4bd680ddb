# Proves that an image check can fail: runs it on a deliberately bad image and passes only if
# the check fails and names what it must.
#
#   cmake -DCHECK=check_symbols.cmake -DNM=<nm> -DELF=<leaky image> -DEXPECT=<regex> -P expect_check_fails.cmake
#   cmake -DCHECK=check_divisions.cmake -DOBJDUMP=<objdump> -DELF=<leaky image> -DEXPECT=<regex> -P ...
#   cmake -DCHECK=check_budget.cmake -DSIZE=<size> -DELF=<image> -DMEMORY=ram -DBUDGET=<too few bytes> -DEXPECT=<regex> -P ...
cmake_minimum_required(VERSION 3.25)
execute_process(
  COMMAND ${CMAKE_COMMAND} -DNM=${NM} -DOBJDUMP=${OBJDUMP} -DSIZE=${SIZE} -DMEMORY=${MEMORY} -DBUDGET=${BUDGET} -DELF=${ELF}
          -P ${CMAKE_CURRENT_LIST_DIR}/${CHECK}
  OUTPUT_VARIABLE output
  ERROR_VARIABLE errors
  RESULT_VARIABLE status)
message("${output}${errors}")
if(status EQUAL 0)
  message(FATAL_ERROR "${CHECK} passed ${ELF}, which it must reject ('${EXPECT}')")
endif()
# message() wraps long lines where it likes (the wrap moves with the length of the build path):
# the expectation is matched against the message with its white space collapsed.
string(REGEX REPLACE "[ \t\r\n]+" " " flat_errors "${errors}")
if(NOT flat_errors MATCHES "${EXPECT}")
  message(FATAL_ERROR "${CHECK} failed on ${ELF}, but did not name '${EXPECT}'")
endif()
message("${CHECK} rejects ${ELF} as it must")
