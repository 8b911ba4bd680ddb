# cmake -DSOURCE_DIR=<iecoop> -DPREFIX=<installed iecoop> -DWORK_DIR=<dir> -DCOMPILER=<c++>
#       -DVERSION=<iecoop's version> -P pkg_config.cmake
# A Make project finds the installed iecoop through pkg-config (iecoop.pc), builds the
# consumer program with its flags and runs it; pkg-config reports iecoop's version.
cmake_minimum_required(VERSION 3.25)
file(REMOVE_RECURSE ${WORK_DIR})
file(MAKE_DIRECTORY ${WORK_DIR})
find_program(PKG_CONFIG pkg-config REQUIRED)
find_program(MAKE make REQUIRED)
set(ENV{PKG_CONFIG_PATH} ${PREFIX}/share/pkgconfig)
set(STEP_PREFIX pkg_config)
set(step_directory WORKING_DIRECTORY ${WORK_DIR})  # make builds here
include(${CMAKE_CURRENT_LIST_DIR}/step.cmake)
step(${PKG_CONFIG} --modversion iecoop)
string(STRIP "${step_output}" found_version)
if(NOT found_version STREQUAL VERSION)
  message(FATAL_ERROR "pkg_config: iecoop.pc says version ${found_version}, the project is ${VERSION}")
endif()
step(${PKG_CONFIG} --cflags iecoop)
# The flags name the installed headers (the .pc file is relocatable: ${pcfiledir}).
file(REAL_PATH ${PREFIX}/include include_dir)
string(STRIP "${step_output}" cflags)
string(REGEX REPLACE "^-I" "" flag_dir "${cflags}")
string(REGEX REPLACE " .*$" "" flag_dir "${flag_dir}")
file(REAL_PATH ${flag_dir} flag_dir)
if(NOT flag_dir STREQUAL include_dir)
  message(FATAL_ERROR "pkg_config: --cflags gives ${cflags}, not the installed headers' ${include_dir}")
endif()
step(${MAKE} -f ${SOURCE_DIR}/tests/consumer/makefile/Makefile SOURCE_DIR=${SOURCE_DIR}/tests/consumer
     CXX=${COMPILER} check)
message("pkg_config: a Make project built and ran with pkg-config's flags for iecoop ${found_version}")
