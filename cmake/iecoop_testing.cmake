# iecoop_discover_tests(<target> [PROPERTIES <name> <value>...] [EXTRA_ARGS <argument>...])
#
# Registers each doctest test case of the test program <target> (built with the test kit,
# docs/testing.md) as a CTest test named `<suite>.<case>` (`<case>` outside a TEST_SUITE),
# labelled with its suite, after each build of the target. `ctest --output-junit junit.xml`
# then writes one JUnit testcase per test case, named after its suite, with the case's output
# (the failed checks, the faults) in the testcase's <system-out>.
#
# Like doctest_discover_tests, but with the suites in the names: CI servers group JUnit test
# cases by the part of the name before the last dot.
function(iecoop_discover_tests target)
  cmake_parse_arguments(PARSE_ARGV 1 arg "" "" "PROPERTIES;EXTRA_ARGS")
  set(ctest_file "${CMAKE_CURRENT_BINARY_DIR}/${target}_iecoop_tests.cmake")
  set(include_file "${CMAKE_CURRENT_BINARY_DIR}/${target}_iecoop_include.cmake")
  # Lists go through the command line with their semicolons as $<SEMICOLON>.
  string(REPLACE ";" "$<SEMICOLON>" properties "${arg_PROPERTIES}")
  string(REPLACE ";" "$<SEMICOLON>" extra_args "${arg_EXTRA_ARGS}")
  add_custom_command(TARGET ${target} POST_BUILD
    BYPRODUCTS ${ctest_file}
    COMMAND ${CMAKE_COMMAND} -D TEST_EXECUTABLE=$<TARGET_FILE:${target}> -D CTEST_FILE=${ctest_file}
            -D TEST_PROPERTIES=${properties} -D TEST_EXTRA_ARGS=${extra_args}
            -D TEST_WORKING_DIR=${CMAKE_CURRENT_BINARY_DIR} -P ${CMAKE_CURRENT_FUNCTION_LIST_DIR}/iecoop_testing_add_tests.cmake
    VERBATIM)
  file(WRITE ${include_file}
       "if(EXISTS \"${ctest_file}\")\n  include(\"${ctest_file}\")\nelse()\n"
       "  add_test(${target}_NOT_BUILT ${target}_NOT_BUILT)\nendif()\n")
  set_property(DIRECTORY APPEND PROPERTY TEST_INCLUDE_FILES ${include_file})
endfunction()
