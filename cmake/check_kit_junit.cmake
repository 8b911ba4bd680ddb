# cmake -DPROGRAM=<faulty test program> -DWORK=<dir> -DDISCOVER=<iecoop_testing_add_tests.cmake>
#       -DCTEST=<ctest> -P check_kit_junit.cmake
# The test kit's reports, read by a real XML parser (xmllint): tests/kit/faulty.cpp has six
# test cases in suite DIV_PRG, of which "divides by zero" faults in task Fast and "prints a
# WORD as ST does" and "prints ARRAYs as ST does" fail a check. Both ways of running it must
# report the six, the three failures with their messages, the cases after the fault as run and
# passed, and the case whose name holds ';', '[', '<', '&' and a quote as run, under its name:
#   1. the program alone, with doctest's JUnit reporter (one process for all cases);
#   2. CTest over the tests iecoop_discover_tests registers, with ctest --output-junit.
cmake_minimum_required(VERSION 3.25)
find_program(XMLLINT xmllint)
if(NOT XMLLINT)
  message(FATAL_ERROR "check_kit_junit: xmllint not found (Debian: apt-get install libxml2-utils)")
endif()
file(REMOVE_RECURSE ${WORK})
file(MAKE_DIRECTORY ${WORK})

# xpath(<file> <expression> <expected>): the XPath expression's string value in the file.
function(xpath file expression expected)
  execute_process(COMMAND ${XMLLINT} --xpath "${expression}" ${file} OUTPUT_VARIABLE value ERROR_VARIABLE error
                  RESULT_VARIABLE status)
  string(STRIP "${value}" value)
  if(NOT status EQUAL 0 OR NOT value STREQUAL expected)
    message(FATAL_ERROR "check_kit_junit: in ${file}, ${expression} is '${value}' (${error}), not '${expected}'")
  endif()
endfunction()
function(well_formed file)
  execute_process(COMMAND ${XMLLINT} --noout ${file} RESULT_VARIABLE status ERROR_VARIABLE error)
  if(NOT status EQUAL 0)
    message(FATAL_ERROR "check_kit_junit: ${file} is not well-formed XML: ${error}")
  endif()
endfunction()
set(odd_name "runs 3 cycles; then reads [GVL.iResult <> 0 & 'ok'")  # XPath: in "..."
set(fault_text "iecoop fault: division by zero: integer division or MOD by zero; the result is 0 (task Fast, program DIV_PRG, cycle clock T#10ms)")

# 1. One process, doctest's JUnit reporter: the fault fails its case, the run goes on.
execute_process(COMMAND ${PROGRAM} --reporters=junit --out=${WORK}/doctest.xml RESULT_VARIABLE status)
if(status EQUAL 0)
  message(FATAL_ERROR "check_kit_junit: the faulty test program passed")
endif()
well_formed(${WORK}/doctest.xml)
xpath(${WORK}/doctest.xml "count(//testcase)" "6")
xpath(${WORK}/doctest.xml "count(//testcase[failure])" "3")
xpath(${WORK}/doctest.xml "string(//testcase[@name='divides by zero']/failure/@message)" "${fault_text}")
xpath(${WORK}/doctest.xml "string(//testcase[@name='prints a WORD as ST does']/failure/@message)" "16#00FF == 254")
xpath(${WORK}/doctest.xml "string(//testcase[@name='prints ARRAYs as ST does']/failure/@message)" "[1, 2, 4] == [1, 2, 3]")
xpath(${WORK}/doctest.xml "count(//testcase[@name='runs after' and @status='run' and not(failure)])" "1")
xpath(${WORK}/doctest.xml "count(//testcase[@name=\"${odd_name}\" and @status='run' and not(failure)])" "1")

# 2. CTest: one test per case, named <suite>.<case>, from iecoop_discover_tests's script.
execute_process(COMMAND ${CMAKE_COMMAND} -D TEST_EXECUTABLE=${PROGRAM} -D CTEST_FILE=${WORK}/tests.cmake
                        -D TEST_WORKING_DIR=${WORK} -P ${DISCOVER} RESULT_VARIABLE status)
if(NOT status EQUAL 0)
  message(FATAL_ERROR "check_kit_junit: the discovery script failed")
endif()
file(WRITE ${WORK}/CTestTestfile.cmake "include(\"${WORK}/tests.cmake\")\n")
execute_process(COMMAND ${CTEST} --test-dir ${WORK} --output-junit ${WORK}/ctest.xml OUTPUT_VARIABLE output
                RESULT_VARIABLE status)
if(status EQUAL 0)
  message(FATAL_ERROR "check_kit_junit: ctest passed the faulty tests:\n${output}")
endif()
well_formed(${WORK}/ctest.xml)
xpath(${WORK}/ctest.xml "count(/testsuite/testcase)" "6")
xpath(${WORK}/ctest.xml "string(/testsuite/@failures)" "3")
xpath(${WORK}/ctest.xml "string(//testcase[@name='DIV_PRG.divides by zero']/@status)" "fail")
xpath(${WORK}/ctest.xml "count(//testcase[@name='DIV_PRG.divides by zero']/system-out[contains(., '${fault_text}')])" "1")
xpath(${WORK}/ctest.xml "string(//testcase[@name='DIV_PRG.prints a WORD as ST does']/@status)" "fail")
xpath(${WORK}/ctest.xml "count(//testcase[@name='DIV_PRG.prints a WORD as ST does']/system-out[contains(., 'CHECK( 16#00FF == 254 )')])" "1")
xpath(${WORK}/ctest.xml "string(//testcase[@name='DIV_PRG.prints ARRAYs as ST does']/@status)" "fail")
xpath(${WORK}/ctest.xml "count(//testcase[@name='DIV_PRG.prints ARRAYs as ST does']/system-out[contains(., 'CHECK( [1, 2, 4] == [1, 2, 3] )')])" "1")
# Registered under its own name, and it ran: a filter that matched no case would pass too.
xpath(${WORK}/ctest.xml "string(//testcase[@name=\"DIV_PRG.${odd_name}\"]/@status)" "run")
xpath(${WORK}/ctest.xml "count(//testcase[@name=\"DIV_PRG.${odd_name}\"]/system-out[contains(., 'test cases: 1 | 1 passed')])" "1")
xpath(${WORK}/ctest.xml "string(//testcase[@name='DIV_PRG.runs before']/@status)" "run")
xpath(${WORK}/ctest.xml "string(//testcase[@name='DIV_PRG.runs after']/@status)" "run")
message(STATUS "check_kit_junit: both reports name the six cases, the fault and the failed checks")
