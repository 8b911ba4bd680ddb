# cmake -DCTEST=<ctest> -P run_ctest.cmake, in a consumer's build directory: runs its tests
# with a JUnit report and reads that with xmllint: every test passed, the kit's test cases
# named <suite>.<case>.
cmake_minimum_required(VERSION 3.25)
execute_process(COMMAND ${CTEST} --output-on-failure --output-junit junit.xml RESULT_VARIABLE status)
if(NOT status EQUAL 0)
  message(FATAL_ERROR "run_ctest: the consumer's tests failed")
endif()
find_program(XMLLINT xmllint REQUIRED)
foreach(check IN ITEMS "count(//testcase[@status!='run'])=0"
                       "count(//testcase[starts-with(@name, 'FB_Valve.') or starts-with(@name, 'PLC_PRG.')])=4"
                       "count(//testcase[@name='FB_Valve.times out after tMax'])=1"
                       "count(//testcase[@name='PLC_PRG.a share of 0 divides by zero'])=1")
  string(REGEX MATCH "^(.*)=([0-9]+)$" _ "${check}")
  execute_process(COMMAND ${XMLLINT} --xpath "${CMAKE_MATCH_1}" junit.xml OUTPUT_VARIABLE value)
  string(STRIP "${value}" value)
  if(NOT value STREQUAL CMAKE_MATCH_2)
    message(FATAL_ERROR "run_ctest: in junit.xml, ${CMAKE_MATCH_1} is ${value}, not ${CMAKE_MATCH_2}")
  endif()
endforeach()
message(STATUS "run_ctest: the consumer's tests passed; junit.xml has the kit's cases by suite")
