# Runs PROGRAM (with the optional ARGS) and passes only if it terminates abnormally (non-zero
# exit or a signal) and its output matches EXPECT. Used for the fault paths that must stop
# the program with a readable message.
cmake_minimum_required(VERSION 3.25)
execute_process(COMMAND "${PROGRAM}" ${ARGS} RESULT_VARIABLE result OUTPUT_VARIABLE output ERROR_VARIABLE output)
if(result EQUAL 0)
  message(FATAL_ERROR "${PROGRAM} exited normally; it should have been stopped.\nOutput:\n${output}")
endif()
if(NOT output MATCHES "${EXPECT}")
  message(FATAL_ERROR "${PROGRAM} stopped (${result}) without the expected message '${EXPECT}'.\nOutput:\n${output}")
endif()
message(STATUS "stopped as expected (${result}): ${output}")
