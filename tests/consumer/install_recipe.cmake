# cmake -DSOURCE_DIR=<iecoop> -DWORK_DIR=<dir> -DCOMPILER=<c++> -DGENERATOR=<gen>
#       [-DHIDE_PACKAGES=ON] -P install_recipe.cmake
# The README's install recipe, as a user runs it: a plain configure of iecoop (no options), an
# install right after it (nothing needs building: iecoop is header-only), then a project
# outside the tree finds the installed package and builds and runs a program with it; and the
# build step builds nothing, whatever is installed on the machine (iecoop's own tests,
# examples, benchmarks and tools are built only when asked for). HIDE_PACKAGES: doctest, fmt
# and Google Benchmark hidden from find_package, as on a machine without them (the package
# then has no test kit).
cmake_minimum_required(VERSION 3.25)
file(REMOVE_RECURSE ${WORK_DIR})
set(build ${WORK_DIR}/build)
set(prefix ${WORK_DIR}/prefix)
set(STEP_PREFIX install_recipe)
include(${CMAKE_CURRENT_LIST_DIR}/step.cmake)
set(hide)
set(kit_options -DIECOOP_CONSUMER_KIT=OFF -DIECOOP_EXPECT_NO_KIT=ON)
if(HIDE_PACKAGES)
  set(hide -DCMAKE_DISABLE_FIND_PACKAGE_doctest=TRUE -DCMAKE_DISABLE_FIND_PACKAGE_fmt=TRUE
           -DCMAKE_DISABLE_FIND_PACKAGE_benchmark=TRUE)
else()
  set(kit_options -DIECOOP_CONSUMER_KIT=ON)
endif()
step(${CMAKE_COMMAND} -S ${SOURCE_DIR} -B ${build} -G ${GENERATOR} -DCMAKE_CXX_COMPILER=${COMPILER}
     -DCMAKE_BUILD_TYPE=Release ${hide})
step(${CMAKE_COMMAND} --install ${build} --prefix ${prefix})
foreach(file include/iecoop/iecoop.hpp include/iecoop/runtime/scheduler.hpp share/cmake/iecoop/iecoopConfig.cmake
             share/pkgconfig/iecoop.pc share/cmake/iecoop/firmware/cmake/arm-none-eabi.cmake
             share/cmake/iecoop/firmware/template/CMakeLists.txt)
  if(NOT EXISTS ${prefix}/${file})
    message(FATAL_ERROR "install_recipe: ${file} was not installed under ${prefix}")
  endif()
endforeach()
foreach(file bin/iecoop-check bin/iecoop-replay share/cmake/iecoop/iecoopCheckTargets.cmake)
  if(EXISTS ${prefix}/${file})
    message(FATAL_ERROR "install_recipe: ${file} was installed, but the tools were not asked for")
  endif()
endforeach()
step(${CMAKE_CTEST_COMMAND} --build-and-test ${SOURCE_DIR}/tests/consumer/find_package ${WORK_DIR}/consumer
     --build-generator ${GENERATOR}
     --build-options -DCMAKE_CXX_COMPILER=${COMPILER} -DCMAKE_PREFIX_PATH=${prefix} -DIECOOP_EXPECT_CHECK=OFF
                     ${kit_options}
     --test-command iecoop_consumer)
# The recipe's build step: nothing of iecoop's own is configured, so nothing is compiled.
step(${CMAKE_COMMAND} --build ${build})
if(step_output MATCHES "Building CXX|Linking CXX")
  message(FATAL_ERROR "install_recipe: the plain build compiled something; it must build nothing")
endif()
foreach(part tests examples bench tools/replay tools/check)
  if(EXISTS ${build}/${part})
    message(FATAL_ERROR "install_recipe: a plain configure configured iecoop's ${part}")
  endif()
endforeach()
if(HIDE_PACKAGES)
  message("install_recipe: configured without doctest, fmt and Google Benchmark, installed, and found")
else()
  message("install_recipe: configured with every package installed, installed without a build, and found")
endif()
