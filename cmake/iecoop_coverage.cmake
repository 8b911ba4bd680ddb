# iecoop_coverage(<target> SOURCES <file or folder>... [OUTPUT_DIRECTORY <dir>] [ARGS <argument>...])
#
# Line and branch coverage of the user's own POUs by a test program written with the test kit
# (docs/testing.md, "Coverage"), as CODESYS's Professional Developer Edition and TcUnit users
# have it. <target> is compiled and linked with --coverage (g++ or clang++; build it without
# optimisation, e.g. CMAKE_BUILD_TYPE=Debug, or the lines and branches reported are the
# optimiser's), and the target <target>_coverage
#   1. deletes the counts of earlier runs,
#   2. runs <target> (every test case; ARGS are passed to it),
#   3. runs gcovr (Debian: apt-get install gcovr) over the counts, which writes
#      <dir>/index.html (an HTML report with a page per file, lines and branches) and
#      <dir>/coverage.xml (Cobertura, for GitLab's and Jenkins' coverage views), and prints a
#      summary per file.
# Only the files SOURCES names are reported (a folder: every file below it): the POUs, not
# iecoop's headers, doctest's or the test files. <dir> is <build dir>/<target>_coverage unless
# given. Branches that only an exception can take are left out (iecoop's code throws none).
function(iecoop_coverage target)
  cmake_parse_arguments(PARSE_ARGV 1 arg "" "OUTPUT_DIRECTORY" "SOURCES;ARGS")
  if(NOT TARGET ${target})
    message(FATAL_ERROR "iecoop_coverage(${target}): no such target; call it after add_executable(${target} ...)")
  endif()
  if(NOT arg_SOURCES)
    message(FATAL_ERROR "iecoop_coverage(${target}): name the files or folders of the POUs to report: "
                        "iecoop_coverage(${target} SOURCES src/pous)")
  endif()
  if(NOT arg_OUTPUT_DIRECTORY)
    set(arg_OUTPUT_DIRECTORY ${CMAKE_CURRENT_BINARY_DIR}/${target}_coverage)
  endif()
  find_program(IECOOP_GCOVR gcovr)
  if(NOT IECOOP_GCOVR)
    message(FATAL_ERROR "iecoop_coverage(${target}): gcovr is missing; install it (Debian: apt-get install gcovr)")
  endif()
  # gcov of the compiler's own version reads its counts (clang's through llvm-cov gcov).
  string(REGEX MATCH "^[0-9]+" major "${CMAKE_CXX_COMPILER_VERSION}")
  if(CMAKE_CXX_COMPILER_ID STREQUAL "GNU")
    find_program(IECOOP_GCOV_${major} NAMES gcov-${major} gcov)
    set(gcov "${IECOOP_GCOV_${major}}")
  elseif(CMAKE_CXX_COMPILER_ID MATCHES "Clang")
    find_program(IECOOP_LLVM_COV_${major} NAMES llvm-cov-${major} llvm-cov)
    set(gcov "${IECOOP_LLVM_COV_${major}} gcov")
  else()
    message(FATAL_ERROR "iecoop_coverage(${target}): coverage needs g++ or clang++, not ${CMAKE_CXX_COMPILER_ID}")
  endif()
  if(gcov MATCHES "NOTFOUND")
    message(FATAL_ERROR "iecoop_coverage(${target}): no gcov for ${CMAKE_CXX_COMPILER_ID} ${major} "
                        "(g++: gcov-${major}, Debian's gcc-${major}; clang++: llvm-cov-${major}, Debian's llvm-${major})")
  endif()
  target_compile_options(${target} PRIVATE --coverage)
  target_link_options(${target} PRIVATE --coverage)
  # gcovr's filters are regular expressions over absolute paths: each source's path, escaped.
  set(filters)
  foreach(source IN LISTS arg_SOURCES)
    get_filename_component(source ${source} ABSOLUTE BASE_DIR ${CMAKE_CURRENT_SOURCE_DIR})
    if(NOT EXISTS ${source})
      message(FATAL_ERROR "iecoop_coverage(${target}): SOURCES names ${source}, which does not exist")
    endif()
    string(REGEX REPLACE "([][.+*?()^$|\\\\])" "\\\\\\1" pattern "${source}")
    if(IS_DIRECTORY ${source})
      string(APPEND pattern "/")
    else()
      string(APPEND pattern "$")
    endif()
    list(APPEND filters "${pattern}")  # absolute: gcovr matches it from the start of the path
  endforeach()
  string(REPLACE ";" "$<SEMICOLON>" filters "${filters}")
  string(REPLACE ";" "$<SEMICOLON>" run_args "${arg_ARGS}")
  add_custom_target(${target}_coverage
    COMMAND ${CMAKE_COMMAND} -D EXECUTABLE=$<TARGET_FILE:${target}> -D ARGS=${run_args}
            -D COUNTS_DIR=${CMAKE_CURRENT_BINARY_DIR}/CMakeFiles/${target}.dir -D GCOVR=${IECOOP_GCOVR}
            -D GCOV=${gcov} -D FILTERS=${filters} -D ROOT=${CMAKE_CURRENT_SOURCE_DIR}
            -D OUTPUT_DIRECTORY=${arg_OUTPUT_DIRECTORY}
            -P ${CMAKE_CURRENT_FUNCTION_LIST_DIR}/iecoop_coverage_run.cmake
    DEPENDS ${target}
    COMMENT "iecoop: coverage of ${target}'s POUs: ${arg_OUTPUT_DIRECTORY}/index.html"
    VERBATIM)
endfunction()
