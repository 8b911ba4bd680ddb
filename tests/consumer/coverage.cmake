# cmake -DSOURCE_DIR=<iecoop> -DPREFIX=<installed iecoop> -DWORK_DIR=<dir> -DCOMPILER=<c++>
#       -DGENERATOR=<gen> -P coverage.cmake
# iecoop_coverage() as a user runs it (tests/consumer/coverage): the project is built (Debug),
# its coverage targets run the tests and gcovr, and the reports must say what the tests did:
# FB_Level's ELSIF taken one way only and the line in it never run, in a Cobertura report that
# holds FB_Level's file alone (no iecoop header, no test file), beside an HTML report; and the
# demo's conveyor covered by its tests.
cmake_minimum_required(VERSION 3.25)
file(REMOVE_RECURSE ${WORK_DIR})
set(build ${WORK_DIR}/build)
set(STEP_PREFIX coverage)
include(${CMAKE_CURRENT_LIST_DIR}/step.cmake)
step(${CMAKE_COMMAND} -S ${SOURCE_DIR}/tests/consumer/coverage -B ${build} -G ${GENERATOR}
     -DCMAKE_CXX_COMPILER=${COMPILER} -DCMAKE_BUILD_TYPE=Debug -DCMAKE_PREFIX_PATH=${PREFIX}
     -DIECOOP_SOURCE_DIR=${SOURCE_DIR})
step(${CMAKE_COMMAND} --build ${build} --target plc_tests_coverage conveyor_tests_coverage)

# The lines of coverage_pou.hpp the report is read at.
file(STRINGS ${SOURCE_DIR}/tests/consumer/coverage_pou.hpp pou_lines)
set(number 0)
foreach(line IN LISTS pou_lines)
  math(EXPR number "${number} + 1")
  if(line MATCHES "ELSIF rLevel < 10.0 THEN")
    set(elsif_line ${number})
  elseif(line MATCHES "[(]never run[)]")
    set(never_line ${number})
  elseif(line MATCHES "IF rLevel > 90.0 THEN")
    set(if_line ${number})
  endif()
endforeach()

set(report ${build}/plc_tests_coverage/coverage.xml)
foreach(file ${report} ${build}/plc_tests_coverage/index.html ${build}/conveyor_tests_coverage/coverage.xml
             ${build}/conveyor_tests_coverage/index.html)
  if(NOT EXISTS ${file})
    message(FATAL_ERROR "coverage: no ${file}")
  endif()
endforeach()
file(READ ${report} xml)
string(REGEX MATCHALL "<class [^>]*filename=\"[^\"]*\"" classes "${xml}")
list(LENGTH classes class_count)
if(NOT class_count EQUAL 1 OR NOT classes MATCHES "coverage_pou\\.hpp\"")
  message(FATAL_ERROR "coverage: the report must hold coverage_pou.hpp alone, it holds: ${classes}")
endif()
# Cobertura: <line number="N" hits="H" branch="true" condition-coverage="50% (1/2)">
foreach(check "${if_line}\" hits=\"[1-9][0-9]*\" branch=\"true\" condition-coverage=\"100% \\(2/2\\)"
              "${elsif_line}\" hits=\"[1-9][0-9]*\" branch=\"true\" condition-coverage=\"50% \\(1/2\\)"
              "${never_line}\" hits=\"0\"")
  if(NOT xml MATCHES "<line number=\"${check}")
    message(FATAL_ERROR "coverage: the report lacks <line number=\"${check}...; it is:\n${xml}")
  endif()
endforeach()
file(READ ${build}/conveyor_tests_coverage/coverage.xml conveyor_xml)
if(NOT conveyor_xml MATCHES "filename=\"[^\"]*conveyor\\.hpp\" line-rate=\"(1\\.0|0\\.[5-9])")
  message(FATAL_ERROR "coverage: the conveyor's tests should cover most of conveyor.hpp:\n${conveyor_xml}")
endif()
message("coverage: the untaken ELSIF (line ${elsif_line}) and the line never run (${never_line}) are reported")
