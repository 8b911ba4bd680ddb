# Checks the code a compiler generates for tests/codegen sources (called by CTest through
# `cmake -P`). Compiles SOURCE with COMPILER and FLAGS (a ;-list) to assembly, then:
#   - every pair of functions iecoop_same_<name>_a / iecoop_same_<name>_b must consist of
#     the same instructions (labels and symbol names aside);
#   - every function iecoop_one_indirect_<name> must contain exactly one indirect call or
#     jump (x86-64 AT&T syntax: `call *...` / `jmp *...`).
# Only meaningful for x86-64; CTest registers it only there.
cmake_minimum_required(VERSION 3.25)

set(assembly "${WORK_DIR}/codegen.s")
execute_process(
  COMMAND "${COMPILER}" ${FLAGS} -S -o "${assembly}" "${SOURCE}"
  RESULT_VARIABLE result
  OUTPUT_VARIABLE output
  ERROR_VARIABLE output)
if(NOT result EQUAL 0)
  message(FATAL_ERROR "compiling ${SOURCE} to assembly failed:\n${output}")
endif()

file(STRINGS "${assembly}" lines)
set(current "")
set(functions "")
foreach(line IN LISTS lines)
  if(line MATCHES "^(iecoop_[A-Za-z0-9_]+):")
    set(current "${CMAKE_MATCH_1}")
    list(APPEND functions "${current}")
    set(body_${current} "")
  elseif(current AND line MATCHES "^[ \t]*\\.size[ \t]+${current},")
    set(current "")  # the end of the function, including its cold part
  elseif(current)
    # Instructions only: no directives, no labels; local label and symbol names erased.
    if(line MATCHES "^[ \t]+[a-z]" AND NOT line MATCHES "^[ \t]+\\.")
      string(STRIP "${line}" instruction)
      string(REGEX REPLACE "\\.L[A-Za-z0-9_]+" ".L" instruction "${instruction}")
      string(REGEX REPLACE "[ \t]+" " " instruction "${instruction}")
      list(APPEND body_${current} "${instruction}")
    endif()
  endif()
endforeach()

set(checked 0)
foreach(function IN LISTS functions)
  if(function MATCHES "^iecoop_same_(.+)_a$")
    set(twin "iecoop_same_${CMAKE_MATCH_1}_b")
    if(NOT twin IN_LIST functions)
      message(FATAL_ERROR "${function} has no twin ${twin} in the assembly")
    endif()
    if(NOT body_${function} STREQUAL body_${twin})
      string(REPLACE ";" "\n  " a "${body_${function}}")
      string(REPLACE ";" "\n  " b "${body_${twin}}")
      message(FATAL_ERROR "${function} and ${twin} differ:\n${function}:\n  ${a}\n${twin}:\n  ${b}")
    endif()
    list(LENGTH body_${function} count)
    message(STATUS "${function} = ${twin} (${count} instructions)")
    math(EXPR checked "${checked} + 1")
  elseif(function MATCHES "^iecoop_one_indirect_")
    set(indirect 0)
    foreach(instruction IN LISTS body_${function})
      if(instruction MATCHES "^(call|jmp)[a-z]* \\*")
        math(EXPR indirect "${indirect} + 1")
      endif()
    endforeach()
    if(NOT indirect EQUAL 1)
      string(REPLACE ";" "\n  " body "${body_${function}}")
      message(FATAL_ERROR "${function} makes ${indirect} indirect calls, not 1:\n  ${body}")
    endif()
    message(STATUS "${function}: one indirect call")
    math(EXPR checked "${checked} + 1")
  endif()
endforeach()
if(checked EQUAL 0)
  message(FATAL_ERROR "no iecoop_same_* or iecoop_one_indirect_* function found in ${SOURCE}")
endif()
