# cmake -DSOURCE_DIR=<iecoop> -DWORK_DIR=<dir> -DCOMPILER=<c++> -DGENERATOR=<gen> -P plain_install.cmake
# The README's install recipe on a machine without iecoop's development packages: a plain
# configure of iecoop (doctest, fmt and Google Benchmark hidden from find_package, as if not
# installed), a build and an install; then a project outside the tree finds the installed
# package and builds and runs a program with it.
cmake_minimum_required(VERSION 3.25)
file(REMOVE_RECURSE ${WORK_DIR})
set(build ${WORK_DIR}/build)
set(prefix ${WORK_DIR}/prefix)
function(step)
  execute_process(COMMAND ${ARGN} RESULT_VARIABLE result OUTPUT_VARIABLE out ERROR_VARIABLE err)
  message("${out}${err}")
  if(NOT result EQUAL 0)
    message(FATAL_ERROR "plain_install: failed: ${ARGN}")
  endif()
endfunction()
step(${CMAKE_COMMAND} -S ${SOURCE_DIR} -B ${build} -G ${GENERATOR} -DCMAKE_CXX_COMPILER=${COMPILER}
     -DCMAKE_DISABLE_FIND_PACKAGE_doctest=TRUE -DCMAKE_DISABLE_FIND_PACKAGE_fmt=TRUE
     -DCMAKE_DISABLE_FIND_PACKAGE_benchmark=TRUE -DIECOOP_BUILD_CHECK=OFF)
step(${CMAKE_COMMAND} --build ${build})
step(${CMAKE_COMMAND} --install ${build} --prefix ${prefix})
if(NOT EXISTS ${prefix}/include/iecoop/runtime/scheduler.hpp)
  message(FATAL_ERROR "plain_install: the headers were not installed under ${prefix}/include")
endif()
step(${CMAKE_CTEST_COMMAND} --build-and-test ${SOURCE_DIR}/tests/consumer/find_package ${WORK_DIR}/consumer
     --build-generator ${GENERATOR}
     --build-options -DCMAKE_CXX_COMPILER=${COMPILER} -DCMAKE_PREFIX_PATH=${prefix} -DIECOOP_EXPECT_CHECK=OFF
                   -DIECOOP_CONSUMER_KIT=OFF -DIECOOP_EXPECT_NO_KIT=ON
     --test-command iecoop_consumer)
message("plain_install: configured without doctest, fmt and Google Benchmark, installed, and found")
