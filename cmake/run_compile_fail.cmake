# Runs one compile-fail check (called by CTest through `cmake -P`).
#
# A compile-fail source holds a misuse between `#ifdef IECOOP_COMPILE_FAIL` and `#else`
# and its correct twin after `#else`; its first line is `// EXPECT: <regex>`, and the lines
# right after it may add more `// EXPECT: <regex>` lines.
#   MODE=fail: compiling with -DIECOOP_COMPILE_FAIL must fail, and the compiler's output
#              must match every EXPECT regex (so it fails for the documented reason, and shows
#              the user's own names) within its first 10 lines (a user reads the top of a
#              diagnostic; `// EXPECT-WITHIN: <n>` in the header comment changes the limit).
#              With `// EXPECT-ERRORS: <n>`, the output must hold exactly n errors.
#   MODE=twin: compiling without it must succeed, warnings being errors.
# Inputs: COMPILER, SOURCE, MODE, FLAGS (a ;-list); optionally PCH_FLAGS (a ;-list), the flags
# that use a precompiled <iecoop/iecoop.hpp>, added only for a source whose first include is
# that header (a source that includes a single header must see that header alone).
cmake_minimum_required(VERSION 3.25)

file(STRINGS "${SOURCE}" first_line LIMIT_COUNT 1)
if(NOT first_line MATCHES "^// EXPECT: (.+)$")
  message(FATAL_ERROR "${SOURCE}: the first line must be `// EXPECT: <regex>`")
endif()
file(STRINGS "${SOURCE}" header_lines LIMIT_COUNT 12)
set(expects "")
set(within 10)
set(expected_errors "")
foreach(line IN LISTS header_lines)
  if(line MATCHES "^// EXPECT: (.+)$")
    list(APPEND expects "${CMAKE_MATCH_1}")
  elseif(line MATCHES "^// EXPECT-WITHIN: ([0-9]+)$")
    set(within "${CMAKE_MATCH_1}")
  elseif(line MATCHES "^// EXPECT-ERRORS: ([0-9]+)$")
    set(expected_errors "${CMAKE_MATCH_1}")
  endif()
endforeach()

set(pch "")
if(PCH_FLAGS)
  file(STRINGS "${SOURCE}" includes REGEX "^#include " LIMIT_COUNT 1)
  if(includes STREQUAL "#include <iecoop/iecoop.hpp>")
    set(pch ${PCH_FLAGS})  # first: its include directory must come before the others
  endif()
endif()
set(defines "")
if(MODE STREQUAL "fail")
  set(defines -DIECOOP_COMPILE_FAIL)
endif()

execute_process(
  COMMAND "${COMPILER}" ${pch} ${FLAGS} ${defines} -fsyntax-only "${SOURCE}"
  RESULT_VARIABLE result
  OUTPUT_VARIABLE output
  ERROR_VARIABLE output)

if(MODE STREQUAL "fail")
  if(result EQUAL 0)
    message(FATAL_ERROR "${SOURCE} compiled with -DIECOOP_COMPILE_FAIL, but the misuse must not compile")
  endif()
  string(REGEX MATCHALL ": error: " error_lines "${output}")
  list(LENGTH error_lines errors)
  foreach(expect IN LISTS expects)
    if(NOT output MATCHES "${expect}")
      message(FATAL_ERROR "${SOURCE} failed to compile, but not with the expected diagnostic\n"
                          "expected (regex): ${expect}\ncompiler output:\n${output}")
    endif()
    # The line where the expected text first appears: the text before the first match,
    # counted in newlines (not a walk over a list, which CMake would split wrongly at brackets).
    string(REGEX REPLACE "(${expect}).*" "" before_match "${output}")
    string(REGEX MATCHALL "\n" newlines "${before_match}")
    list(LENGTH newlines found_at)
    math(EXPR found_at "${found_at} + 1")
    if(found_at GREATER within)
      message(FATAL_ERROR "${SOURCE}: the expected diagnostic is at line ${found_at} of the compiler's output, "
                          "not within its first ${within} lines\nexpected (regex): ${expect}\ncompiler output:\n${output}")
    endif()
    message(STATUS "rejected as expected, at line ${found_at}: ${expect}")
  endforeach()
  if(NOT expected_errors STREQUAL "" AND NOT errors EQUAL expected_errors)
    message(FATAL_ERROR "${SOURCE}: ${errors} errors, expected ${expected_errors}\ncompiler output:\n${output}")
  endif()
  message(STATUS "${errors} error(s)")
elseif(MODE STREQUAL "twin")
  if(NOT result EQUAL 0)
    message(FATAL_ERROR "the compiling twin of ${SOURCE} does not compile:\n${output}")
  endif()
else()
  message(FATAL_ERROR "MODE must be fail or twin")
endif()
