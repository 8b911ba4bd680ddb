# cmake -DSOURCE_DIR=<iecoop> -DWORK_DIR=<dir> -DCOMPILER=<c++> -DGENERATOR=<gen> -DVERSION=<version>
#       -DKIND=DEB|TGZ -P packages.cmake
# The package CPack makes of a plain configure (README.md): its contents are checked
# (the headers, the CMake package, iecoop.pc, the licence; nothing of iecoop's tests,
# examples or tools), it is unpacked (not installed on this machine), and a project outside
# the tree finds iecoop in it with find_package and builds and runs a program with it.
cmake_minimum_required(VERSION 3.25)
file(REMOVE_RECURSE ${WORK_DIR})
set(build ${WORK_DIR}/build)
set(unpacked ${WORK_DIR}/unpacked)
file(MAKE_DIRECTORY ${unpacked})
set(STEP_PREFIX packages)
include(${CMAKE_CURRENT_LIST_DIR}/step.cmake)
step(${CMAKE_COMMAND} -S ${SOURCE_DIR} -B ${build} -G ${GENERATOR} -DCMAKE_CXX_COMPILER=${COMPILER}
     -DCMAKE_BUILD_TYPE=Release)
step(${CMAKE_CPACK_COMMAND} -G ${KIND} -B ${WORK_DIR}/out --config ${build}/CPackConfig.cmake)

if(KIND STREQUAL "DEB")
  set(file ${WORK_DIR}/out/iecoop-dev_${VERSION}_all.deb)
  if(NOT EXISTS ${file})
    message(FATAL_ERROR "packages: no ${file}")
  endif()
  find_program(DPKG_DEB dpkg-deb REQUIRED)
  foreach(field Package=iecoop-dev Version=${VERSION} Architecture=all Section=libdevel)
    string(REPLACE "=" ";" pair ${field})
    list(GET pair 0 name)
    list(GET pair 1 expected)
    step(${DPKG_DEB} --field ${file} ${name})
    string(STRIP "${step_output}" value)
    if(NOT value STREQUAL expected)
      message(FATAL_ERROR "packages: the DEB's ${name} is '${value}', not '${expected}'")
    endif()
  endforeach()
  step(${DPKG_DEB} --contents ${file})
  set(listing "${step_output}")
  step(${DPKG_DEB} --extract ${file} ${unpacked})
  set(root ${unpacked}/usr)
else()
  set(file ${WORK_DIR}/out/iecoop-${VERSION}-Linux.tar.gz)
  if(NOT EXISTS ${file})
    message(FATAL_ERROR "packages: no ${file}")
  endif()
  step(${CMAKE_COMMAND} -E tar tzf ${file})
  set(listing "${step_output}")
  file(ARCHIVE_EXTRACT INPUT ${file} DESTINATION ${unpacked})
  set(root ${unpacked}/iecoop-${VERSION}-Linux)
endif()

# What the package holds: every public header, the CMake package, iecoop.pc; nothing else of
# the tree.
file(GLOB_RECURSE headers RELATIVE ${SOURCE_DIR}/include ${SOURCE_DIR}/include/iecoop/*.hpp)
list(LENGTH headers header_count)
foreach(header IN LISTS headers)
  if(NOT EXISTS ${root}/include/${header})
    message(FATAL_ERROR "packages: the ${KIND} package lacks include/${header}")
  endif()
endforeach()
foreach(file share/cmake/iecoop/iecoopConfig.cmake share/cmake/iecoop/iecoopConfigVersion.cmake
             share/cmake/iecoop/iecoopTargets.cmake share/pkgconfig/iecoop.pc share/doc/iecoop/LICENSE
             share/doc/iecoop/CHANGELOG.md share/cmake/iecoop/firmware/cmake/iecoop_firmware.cmake
             share/cmake/iecoop/firmware/boards/microbit/memory.ld)
  if(NOT EXISTS ${root}/${file})
    message(FATAL_ERROR "packages: the ${KIND} package lacks ${file}")
  endif()
endforeach()
if(listing MATCHES "/(tests|examples|bench|embedded|tools|bin)/|\\.(o|a|so)\n")
  message(FATAL_ERROR "packages: the ${KIND} package holds more than the library (${CMAKE_MATCH_0}):\n${listing}")
endif()

step(${CMAKE_CTEST_COMMAND} --build-and-test ${SOURCE_DIR}/tests/consumer/find_package ${WORK_DIR}/consumer
     --build-generator ${GENERATOR}
     --build-options -DCMAKE_CXX_COMPILER=${COMPILER} -DCMAKE_PREFIX_PATH=${root} -DIECOOP_EXPECT_CHECK=OFF
                     -DIECOOP_CONSUMER_KIT=OFF
     --test-command iecoop_consumer)
message("packages: the ${KIND} package holds the ${header_count} headers, the CMake and pkg-config files and "
        "the licence, and a project built with it")
