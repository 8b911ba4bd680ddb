# cmake -D TEST_EXECUTABLE=<program> -D CTEST_FILE=<file> [-D TEST_PROPERTIES=<list>]
#       [-D TEST_EXTRA_ARGS=<list>] [-D TEST_WORKING_DIR=<dir>] -P iecoop_testing_add_tests.cmake
# Writes CTEST_FILE: an add_test() per test case the doctest program lists, named
# `<suite>.<case>` (iecoop_discover_tests, cmake/iecoop_testing.cmake).
cmake_minimum_required(VERSION 3.25)

execute_process(COMMAND "${TEST_EXECUTABLE}" --list-test-cases --reporters=xml --no-version=true
                OUTPUT_VARIABLE listing RESULT_VARIABLE status)
if(NOT status EQUAL 0)
  message(FATAL_ERROR "iecoop_discover_tests: '${TEST_EXECUTABLE} --list-test-cases' failed (${status}):\n${listing}")
endif()

# Every test case is registered, whatever its name holds. CMake's lists split at ';' and group
# what stands between '[' and ']' (so that an unmatched '[' would swallow the cases after it):
# while the listing is parsed these three characters stand as \x01, \x02 and \x03, which no
# test name holds, and they go back into the written script, where CTest keeps them (a bracket
# argument is never split): the test `S.a;b` runs the case `a;b` of suite `S`, and JUnit
# reports it under that name (docs/testing.md).
string(ASCII 1 semicolon)
string(ASCII 2 open_bracket)
string(ASCII 3 close_bracket)
string(REPLACE ";" "${semicolon}" listing "${listing}")
string(REPLACE "[" "${open_bracket}" listing "${listing}")
string(REPLACE "]" "${close_bracket}" listing "${listing}")
function(decoded text out)
  string(REPLACE "${semicolon}" ";" text "${text}")
  string(REPLACE "${open_bracket}" "[" text "${text}")
  string(REPLACE "${close_bracket}" "]" text "${text}")
  set(${out} "${text}" PARENT_SCOPE)
endfunction()

# Quotes are escaped in doctest's attributes (&quot;); so "[^"]*" is one attribute's value. The
# entities' ';' stands as \x01 too.
function(xml_unescape text out)
  string(REPLACE "&quot${semicolon}" "\"" text "${text}")
  string(REPLACE "&apos${semicolon}" "'" text "${text}")
  string(REPLACE "&lt${semicolon}" "<" text "${text}")
  string(REPLACE "&gt${semicolon}" ">" text "${text}")
  string(REPLACE "&amp${semicolon}" "&" text "${text}")
  set(${out} "${text}" PARENT_SCOPE)
endfunction()

# A doctest filter: commas separate filters, so a name's own commas are escaped.
function(doctest_filter text out)
  string(REPLACE "," "\\," text "${text}")
  set(${out} "${text}" PARENT_SCOPE)
endfunction()

# The properties given, but LABELS, which each test gets together with its suite.
set(given_labels "")
set(other_properties "")
set(in_labels FALSE)
foreach(item IN LISTS TEST_PROPERTIES)
  if(item STREQUAL "LABELS")
    set(in_labels TRUE)
  elseif(in_labels)
    list(APPEND given_labels "${item}")
    set(in_labels FALSE)
  else()
    string(APPEND other_properties " [==[${item}]==]")
  endif()
endforeach()

set(script "")
set(names "")
string(REGEX MATCHALL "<TestCase name=\"[^\"]*\"( testsuite=\"[^\"]*\")?" cases "${listing}")
foreach(entry IN LISTS cases)
  string(REGEX MATCH "name=\"([^\"]*)\"" _ "${entry}")
  xml_unescape("${CMAKE_MATCH_1}" case)
  set(suite "")
  if(entry MATCHES "testsuite=\"([^\"]*)\"")
    xml_unescape("${CMAKE_MATCH_1}" suite)
  endif()
  set(name "${case}")
  if(NOT suite STREQUAL "")
    set(name "${suite}.${case}")
  endif()
  if(name IN_LIST names)
    decoded("${name}" shown)
    message(WARNING "iecoop_discover_tests: two test cases are called '${shown}': one CTest test runs both (its "
                    "filter matches both), and reports them as one; give them different names")
    continue()
  endif()
  list(APPEND names "${name}")
  doctest_filter("${case}" case_filter)
  set(arguments "[==[--test-case=${case_filter}]==]")
  set(labels ${given_labels})
  if(NOT suite STREQUAL "")
    doctest_filter("${suite}" suite_filter)
    string(APPEND arguments " [==[--test-suite=${suite_filter}]==]")
    string(REPLACE "${semicolon}" "\\;" suite_label "${suite}")  # one label, not two: LABELS is a list
    list(APPEND labels "${suite_label}")
  endif()
  foreach(argument IN LISTS TEST_EXTRA_ARGS)
    string(APPEND arguments " [==[${argument}]==]")
  endforeach()
  string(APPEND script "add_test([==[${name}]==] [==[${TEST_EXECUTABLE}]==] ${arguments})\n")
  string(APPEND script "set_tests_properties([==[${name}]==] PROPERTIES WORKING_DIRECTORY [==[${TEST_WORKING_DIR}]==]"
                       "${other_properties} LABELS [==[${labels}]==])\n")
endforeach()
decoded("${script}" script)
file(WRITE "${CTEST_FILE}" "${script}")
