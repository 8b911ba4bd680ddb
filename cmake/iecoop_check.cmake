# iecoop_check(<target> [BUILD] [NAME <test name>] [FLAGS <flag>...])
#
# Runs iecoop-check (docs/iecoop-check.md) over the C++ sources of <target>, with their
# compile commands where the build writes compile_commands.json (CMAKE_EXPORT_COMPILE_COMMANDS
# with a Makefile or Ninja generator), else with -std=c++20 and the target's include
# directories and compile definitions (its own and those of the libraries it links; all as -I,
# so that findings in the headers of other libraries are reported too: give those as FLAGS
# -isystem <dir>, or export the compile commands):
#   - as the CTest test <test name> (default: iecoop_check.<target>); call enable_testing();
#   - with BUILD, also in every build, as the target <target>_iecoop_check (part of ALL): a
#     finding fails the build.
# FLAGS are more compiler flags for the checker (-D..., -I...). The checker is the target
# iecoop::check (built with iecoop, or imported by find_package(iecoop)), else the program
# iecoop-check on the PATH; without it, iecoop_check() only warns.
function(iecoop_check target)
  cmake_parse_arguments(PARSE_ARGV 1 arg "BUILD" "NAME" "FLAGS")
  if(NOT TARGET ${target})
    message(FATAL_ERROR "iecoop_check(${target}): there is no target ${target}")
  endif()
  if(TARGET iecoop::check)
    set(checker iecoop::check)
  else()
    find_program(IECOOP_CHECK_EXECUTABLE iecoop-check)
    if(NOT IECOOP_CHECK_EXECUTABLE)
      message(WARNING "iecoop_check(${target}): iecoop-check is not available (build iecoop with libclang's "
                      "headers installed, e.g. Debian's libclang-14-dev); ${target} is not checked")
      return()
    endif()
    set(checker ${IECOOP_CHECK_EXECUTABLE})
  endif()

  get_target_property(sources ${target} SOURCES)
  get_target_property(source_dir ${target} SOURCE_DIR)
  set(files)
  foreach(source IN LISTS sources)
    if(source MATCHES "\\$<" OR NOT source MATCHES "\\.(cpp|cc|cxx|c\\+\\+|C)$")
      continue()  # generated names and headers: headers are checked where a source includes them
    endif()
    cmake_path(ABSOLUTE_PATH source BASE_DIRECTORY ${source_dir})
    list(APPEND files ${source})
  endforeach()
  if(NOT files)
    message(WARNING "iecoop_check(${target}): ${target} has no C++ source to check")
    return()
  endif()

  set(includes "$<TARGET_PROPERTY:${target},INCLUDE_DIRECTORIES>")
  set(definitions "$<TARGET_PROPERTY:${target},COMPILE_DEFINITIONS>")
  set(database)
  if(CMAKE_EXPORT_COMPILE_COMMANDS AND CMAKE_GENERATOR MATCHES "Makefiles|Ninja")
    set(database -p ${CMAKE_BINARY_DIR})
  endif()
  set(command ${checker} ${database} ${files} -- -std=c++20
      "$<$<BOOL:${includes}>:-I$<JOIN:${includes},$<SEMICOLON>-I>>"
      "$<$<BOOL:${definitions}>:-D$<JOIN:${definitions},$<SEMICOLON>-D>>"
      ${arg_FLAGS})

  if(NOT arg_NAME)
    set(arg_NAME iecoop_check.${target})
  endif()
  add_test(NAME ${arg_NAME} COMMAND ${command} COMMAND_EXPAND_LISTS)
  if(arg_BUILD)
    add_custom_target(${target}_iecoop_check ALL COMMAND ${command}
                      COMMENT "iecoop-check: ${target}" COMMAND_EXPAND_LISTS VERBATIM)
  endif()
endfunction()
