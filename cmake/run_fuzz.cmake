# Runs one libFuzzer target (tests/fuzz/CMakeLists.txt): first on every input of its seed corpus,
# then fuzzing for SECONDS seconds. The seeds are copied to WORK_DIR/corpus first, and libFuzzer
# writes only there (new inputs) and to WORK_DIR/artifacts (a crash), never to the source tree.
#   FUZZER=<program> SEEDS=<dir> WORK_DIR=<dir> SECONDS=<n> MAX_LEN=<bytes> [DICT=<file>]
# Fails with libFuzzer's report where the target crashes, leaks, hangs or breaks a property.
cmake_minimum_required(VERSION 3.25)
file(REMOVE_RECURSE "${WORK_DIR}")
file(MAKE_DIRECTORY "${WORK_DIR}/corpus" "${WORK_DIR}/artifacts")
if(IS_DIRECTORY "${SEEDS}")
  file(COPY "${SEEDS}/" DESTINATION "${WORK_DIR}/corpus")
endif()
set(options -max_total_time=${SECONDS} -max_len=${MAX_LEN} -timeout=10 -rss_limit_mb=2048
            -print_final_stats=1 -artifact_prefix=${WORK_DIR}/artifacts/)
if(DICT)
  list(APPEND options -dict=${DICT})
endif()
execute_process(COMMAND "${FUZZER}" ${options} "${WORK_DIR}/corpus"
                RESULT_VARIABLE result OUTPUT_VARIABLE output ERROR_VARIABLE output)
file(GLOB artifacts "${WORK_DIR}/artifacts/*")
if(NOT result EQUAL 0 OR artifacts)
  # The end of libFuzzer's report: the finding, its stack, the input that caused it.
  string(LENGTH "${output}" length)
  if(length GREATER 12000)
    math(EXPR from "${length} - 12000")
    string(SUBSTRING "${output}" ${from} -1 output)
    set(output "...\n${output}")
  endif()
  message(FATAL_ERROR "${FUZZER} failed (exit status ${result}); the input is kept in ${artifacts}\n${output}")
endif()
string(REGEX MATCH "stat::number_of_executed_units: *([0-9]+)" _ "${output}")
set(runs ${CMAKE_MATCH_1})
string(REGEX MATCH "stat::average_exec_per_sec: *([0-9]+)" _ "${output}")
set(speed ${CMAKE_MATCH_1})
string(REGEX MATCHALL "cov: [0-9]+ ft: [0-9]+ corp: [0-9]+" coverage "${output}")
list(GET coverage -1 coverage)  # the last status line's
message(STATUS "${runs} inputs run (${speed}/s), ${coverage} inputs; nothing found")
