# Fails if a firmware image takes more RAM than its budget:
#
#   cmake -DSIZE=<arm-none-eabi-size> -DELF=<image> -DBUDGET=<bytes> -P check_ram.cmake
#
# The RAM is what the size table of docs/embedded.md counts: .data plus .bss (the stack has a
# section of its own, .stack, and is not counted). The scheduler example's budget on the
# Cortex-M3 is issue 39's 1 KiB; a twin with a budget far below the image's RAM proves the
# check can fail.
cmake_minimum_required(VERSION 3.25)
if(NOT DEFINED SIZE OR NOT DEFINED ELF OR NOT DEFINED BUDGET)
  message(FATAL_ERROR "usage: cmake -DSIZE=<size> -DELF=<image> -DBUDGET=<bytes> -P check_ram.cmake")
endif()

execute_process(COMMAND ${SIZE} -A -d ${ELF} OUTPUT_VARIABLE listing RESULT_VARIABLE status)
if(NOT status EQUAL 0)
  message(FATAL_ERROR "${SIZE} failed on ${ELF} (status ${status})")
endif()
set(data 0)
set(bss 0)
string(REPLACE "\n" ";" lines "${listing}")
foreach(line IN LISTS lines)
  if(line MATCHES "^\\.data[ \t]+([0-9]+)")
    set(data ${CMAKE_MATCH_1})
  elseif(line MATCHES "^\\.bss[ \t]+([0-9]+)")
    set(bss ${CMAKE_MATCH_1})
  endif()
endforeach()
if(bss EQUAL 0)
  message(FATAL_ERROR "no .bss section in ${ELF}: not an image of iecoop's linker script?")
endif()
math(EXPR ram "${data} + ${bss}")
if(ram GREATER BUDGET)
  message(FATAL_ERROR "RAM over budget: ${ELF} takes ${ram} bytes (.data ${data} + .bss ${bss}), more than its budget of "
                      "${BUDGET}")
endif()
message(STATUS "${ELF}: ${ram} bytes of RAM (.data ${data} + .bss ${bss}), budget ${BUDGET}")
