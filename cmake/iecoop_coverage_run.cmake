# Run by the target <target>_coverage that iecoop_coverage() (iecoop_coverage.cmake) makes:
# cmake -D EXECUTABLE=... -D ARGS=... -D COUNTS_DIR=... -D GCOVR=... -D GCOV=... -D FILTERS=...
#       -D ROOT=... -D OUTPUT_DIRECTORY=... -P iecoop_coverage_run.cmake
cmake_minimum_required(VERSION 3.25)
# 1. The counts of earlier runs (a ctest run, the last coverage run) go: this run's only.
file(GLOB_RECURSE old_counts ${COUNTS_DIR}/*.gcda)
if(old_counts)
  file(REMOVE ${old_counts})
endif()
# 2. The test program. A failing test case still gives its coverage; the run's status is
#    reported after the report.
execute_process(COMMAND ${EXECUTABLE} ${ARGS} RESULT_VARIABLE tests_result)
# 3. gcovr: the HTML and Cobertura reports and a summary, of the filtered files only.
file(MAKE_DIRECTORY ${OUTPUT_DIRECTORY})
set(filter_options)
foreach(filter IN LISTS FILTERS)
  list(APPEND filter_options --filter ${filter})
endforeach()
execute_process(
  COMMAND ${GCOVR} --root ${ROOT} ${filter_options} --gcov-executable ${GCOV} --exclude-throw-branches
          --exclude-unreachable-branches --html-details ${OUTPUT_DIRECTORY}/index.html
          --cobertura ${OUTPUT_DIRECTORY}/coverage.xml --txt - ${COUNTS_DIR}
  RESULT_VARIABLE gcovr_result)
if(NOT gcovr_result EQUAL 0)
  message(FATAL_ERROR "iecoop: gcovr failed (${gcovr_result})")
endif()
message("iecoop: coverage report ${OUTPUT_DIRECTORY}/index.html, Cobertura ${OUTPUT_DIRECTORY}/coverage.xml")
if(NOT tests_result EQUAL 0)
  message(FATAL_ERROR "iecoop: the test program failed (${tests_result}); the coverage above is of that run")
endif()
