# Runs one shard of a doctest program's test cases (called by CTest through `cmake -P`):
# the cases in doctest's file order, split into SHARDS slices of nearly equal count; this
# runs slice SHARD (0-based) in one process. IECOOP_UNIT_TEST_SHARDS (tests/CMakeLists.txt)
# registers the shards instead of one CTest test per case, for a build where starting the
# program is expensive (the sanitizer build: each start costs more than most cases).
# Inputs: PROGRAM, SHARD, SHARDS.
cmake_minimum_required(VERSION 3.25)

execute_process(COMMAND "${PROGRAM}" --count RESULT_VARIABLE result OUTPUT_VARIABLE output ERROR_VARIABLE output)
if(NOT result EQUAL 0 OR NOT output MATCHES "test cases passing the current filters: ([0-9]+)")
  message(FATAL_ERROR "${PROGRAM} --count did not say how many test cases it has:\n${output}")
endif()
set(count ${CMAKE_MATCH_1})
# doctest's --first and --last count from 1, in the order --order-by=file gives.
math(EXPR first "${SHARD} * ${count} / ${SHARDS} + 1")
math(EXPR last "(${SHARD} + 1) * ${count} / ${SHARDS}")
if(first GREATER last)
  message(STATUS "shard ${SHARD} of ${SHARDS}: no test case (${count} in all)")
  return()
endif()
message(STATUS "shard ${SHARD} of ${SHARDS}: test cases ${first} to ${last} of ${count}")
execute_process(COMMAND "${PROGRAM}" --order-by=file --first=${first} --last=${last} RESULT_VARIABLE result)
if(NOT result EQUAL 0)
  message(FATAL_ERROR "test cases ${first} to ${last} of ${PROGRAM} failed (exit status ${result})")
endif()
