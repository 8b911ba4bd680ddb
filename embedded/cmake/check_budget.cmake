# Fails if a firmware image takes more flash or RAM than its budget:
#
#   cmake -DSIZE=<arm-none-eabi-size> -DELF=<image> -DMEMORY=flash|ram -DBUDGET=<bytes> -P check_budget.cmake
#
# Counted as the size table of docs/embedded.md counts (embedded/size_table.sh): the flash is
# what the image keeps there, .vectors, .text, .ARM.exidx and .init_array plus the first values
# of .data; the RAM is .data plus .bss (the stack has a section of its own, .stack, and is not
# counted). The scheduler example's budgets on the Cortex-M3 are issue 39's 8 KiB and 1 KiB;
# twins with budgets far below the image's prove the check can fail.
cmake_minimum_required(VERSION 3.25)
if(NOT DEFINED SIZE OR NOT DEFINED ELF OR NOT DEFINED BUDGET OR NOT MEMORY MATCHES "^(flash|ram)$")
  message(FATAL_ERROR "usage: cmake -DSIZE=<size> -DELF=<image> -DMEMORY=flash|ram -DBUDGET=<bytes> -P check_budget.cmake")
endif()

execute_process(COMMAND ${SIZE} -A -d ${ELF} OUTPUT_VARIABLE listing RESULT_VARIABLE status)
if(NOT status EQUAL 0)
  message(FATAL_ERROR "${SIZE} failed on ${ELF} (status ${status})")
endif()
set(text 0)
set(data 0)
set(bss 0)
string(REPLACE "\n" ";" lines "${listing}")
foreach(line IN LISTS lines)
  if(line MATCHES "^\\.(vectors|text|ARM\\.exidx|init_array)[ \t]+([0-9]+)")
    math(EXPR text "${text} + ${CMAKE_MATCH_2}")
  elseif(line MATCHES "^\\.data[ \t]+([0-9]+)")
    set(data ${CMAKE_MATCH_1})
  elseif(line MATCHES "^\\.bss[ \t]+([0-9]+)")
    set(bss ${CMAKE_MATCH_1})
  endif()
endforeach()
if(bss EQUAL 0 OR text EQUAL 0)
  message(FATAL_ERROR "no .text or .bss section in ${ELF}: not an image of iecoop's linker script?")
endif()
if(MEMORY STREQUAL "flash")
  math(EXPR used "${text} + ${data}")
  set(parts "code and constants ${text} + .data ${data}")
else()
  math(EXPR used "${data} + ${bss}")
  set(parts ".data ${data} + .bss ${bss}")
endif()
if(used GREATER BUDGET)
  message(FATAL_ERROR "${MEMORY} over budget: ${ELF} takes ${used} bytes (${parts}), more than its budget of ${BUDGET}")
endif()
message(STATUS "${ELF}: ${used} bytes of ${MEMORY} (${parts}), budget ${BUDGET}")
