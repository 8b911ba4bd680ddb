# Runs one compile-fail check (called by CTest through `cmake -P`).
#
# A compile-fail source holds a misuse between `#ifdef IECOOP_COMPILE_FAIL` and `#else`
# and its correct twin after `#else`; its first line is `// EXPECT: <regex>`.
#   MODE=fail: compiling with -DIECOOP_COMPILE_FAIL must fail, and the compiler's output
#              must match the EXPECT regex (so it fails for the documented reason).
#   MODE=twin: compiling without it must succeed, warnings being errors.
# Inputs: COMPILER, SOURCE, MODE, FLAGS (a ;-list).
cmake_minimum_required(VERSION 3.25)

file(STRINGS "${SOURCE}" first_line LIMIT_COUNT 1)
if(NOT first_line MATCHES "^// EXPECT: (.+)$")
  message(FATAL_ERROR "${SOURCE}: the first line must be `// EXPECT: <regex>`")
endif()
set(expect "${CMAKE_MATCH_1}")

set(defines "")
if(MODE STREQUAL "fail")
  set(defines -DIECOOP_COMPILE_FAIL)
endif()

execute_process(
  COMMAND "${COMPILER}" ${FLAGS} ${defines} -fsyntax-only "${SOURCE}"
  RESULT_VARIABLE result
  OUTPUT_VARIABLE output
  ERROR_VARIABLE output)

if(MODE STREQUAL "fail")
  if(result EQUAL 0)
    message(FATAL_ERROR "${SOURCE} compiled with -DIECOOP_COMPILE_FAIL, but the misuse must not compile")
  endif()
  if(NOT output MATCHES "${expect}")
    message(FATAL_ERROR "${SOURCE} failed to compile, but not with the expected diagnostic\n"
                        "expected (regex): ${expect}\ncompiler output:\n${output}")
  endif()
  message(STATUS "rejected as expected: ${expect}")
elseif(MODE STREQUAL "twin")
  if(NOT result EQUAL 0)
    message(FATAL_ERROR "the compiling twin of ${SOURCE} does not compile:\n${output}")
  endif()
else()
  message(FATAL_ERROR "MODE must be fail or twin")
endif()
