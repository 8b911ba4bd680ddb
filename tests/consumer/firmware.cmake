# cmake -DSOURCE_DIR=<iecoop> -DPREFIX=<installed iecoop> -DWORK_DIR=<dir> -DCORE=<cortex-m...>
#       [-DADD_SUBDIRECTORY=ON] -P firmware.cmake
# A user's own firmware project (docs/embedded.md, "Your own firmware project"): the template
# as the installed package ships it, configured with the installed toolchain file for CORE and
# find_package(iecoop) (with ADD_SUBDIRECTORY: the source tree's template, toolchain file and
# add_subdirectory), built, and run under QEMU on the core's board by its own test, which
# checks what the controller did.
cmake_minimum_required(VERSION 3.25)
file(REMOVE_RECURSE ${WORK_DIR})
file(MAKE_DIRECTORY ${WORK_DIR})
set(STEP_PREFIX firmware)
include(${CMAKE_CURRENT_LIST_DIR}/step.cmake)
if(ADD_SUBDIRECTORY)
  set(template ${SOURCE_DIR}/embedded/template)
  set(toolchain ${SOURCE_DIR}/embedded/cmake/arm-none-eabi.cmake)
  set(find -DIECOOP_SOURCE_DIR=${SOURCE_DIR})
  set(how "add_subdirectory")
else()
  set(template ${PREFIX}/share/cmake/iecoop/firmware/template)
  set(toolchain ${PREFIX}/share/cmake/iecoop/firmware/cmake/arm-none-eabi.cmake)
  set(find -DCMAKE_PREFIX_PATH=${PREFIX})
  set(how "find_package")
endif()
# The user copies the template: build the copy, not the original.
file(COPY ${template}/ DESTINATION ${WORK_DIR}/source)
step(${CMAKE_COMMAND} -S ${WORK_DIR}/source -B ${WORK_DIR}/build --toolchain ${toolchain} -DIECOOP_CORTEX_M=${CORE}
     -DCMAKE_BUILD_TYPE=MinSizeRel -DCONTROLLER_QEMU_RUN_MS=500 ${find})
step(${CMAKE_COMMAND} --build ${WORK_DIR}/build)
step(${CMAKE_CTEST_COMMAND} --test-dir ${WORK_DIR}/build --output-on-failure)
if(NOT step_output MATCHES "100% tests passed, 0 tests failed out of 1")
  message(FATAL_ERROR "firmware: the template's test did not run and pass:\n${step_output}")
endif()
message("firmware: a user's project for ${CORE} (${how}) built and ran under QEMU")
