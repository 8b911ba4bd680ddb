# Fails if code that may run in a task cycle divides 64-bit integers in software:
#
#   cmake -DOBJDUMP=<arm-none-eabi-objdump> -DELF=<image> -P check_divisions.cmake
#
# A 32-bit Cortex-M has no 64-bit divide instruction (a Cortex-M0+ has none at all): `a / b` on
# 64-bit operands calls libgcc's __aeabi_uldivmod or __aeabi_ldivmod, hundreds of cycles on a
# small core. The disassembly is the evidence: every function that calls one of them is listed,
# and each must be one of those that docs/embedded.md ("64-bit divisions") names as outside the
# task cycle or as measured there: the scheduler's skip_missed_releases (a cyclic task that
# fell behind) and freewheeling_pause (a freewheeling task's pause), the text of numbers the
# examples print at the end (firmware::put, iecoop's to_text and the trace writers), and the
# division routines themselves. The `leaky_division` image proves the check can fail
# (expect_check_fails.cmake).
cmake_minimum_required(VERSION 3.25)
if(NOT DEFINED OBJDUMP OR NOT DEFINED ELF)
  message(FATAL_ERROR "usage: cmake -DOBJDUMP=<objdump> -DELF=<image> -P check_divisions.cmake")
endif()

execute_process(COMMAND ${OBJDUMP} -d --demangle ${ELF} OUTPUT_VARIABLE listing RESULT_VARIABLE status)
if(NOT status EQUAL 0)
  message(FATAL_ERROR "${OBJDUMP} failed on ${ELF} (status ${status})")
endif()

set(division_routines "__aeabi_uldivmod|__aeabi_ldivmod|__udivmoddi4|__divmoddi4|__udivdi3|__divdi3|__umoddi3|__moddi3")
set(allowed "skip_missed_releases|freewheeling_pause|firmware::put|write_unsigned|trace_text|put_decimal|write_vcd|write_csv|to_text|${division_routines}")

string(REPLACE ";" "\\;" listing "${listing}")  # a demangled name may hold `;`: keep lines whole
string(REPLACE "\n" ";" lines "${listing}")
set(function "")
set(found "")
foreach(line IN LISTS lines)
  if(line MATCHES "^[0-9a-f]+ <(.*)>:$")
    set(function "${CMAKE_MATCH_1}")
  elseif(line MATCHES "[ \t]b(l|lx|\\.w)?[ \t]+[0-9a-f]+ <(${division_routines})>")
    set(routine "${CMAKE_MATCH_2}")
    if(NOT function MATCHES "${allowed}")
      list(APPEND found "${function} calls ${routine}")
    endif()
  endif()
endforeach()
list(REMOVE_DUPLICATES found)
if(found)
  string(REPLACE ";" "\n  " found "${found}")
  message(FATAL_ERROR "${ELF} divides 64-bit integers in software where a task cycle may run:\n  ${found}\n"
                      "use a division by a constant (iecoop/detail/constant_division.hpp) or move it out of the cycle")
endif()
message("${ELF}: no 64-bit division outside the functions docs/embedded.md names")
