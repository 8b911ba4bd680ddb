# Fails if a firmware image divides 64-bit integers in software:
#
#   cmake -DOBJDUMP=<arm-none-eabi-objdump> -DELF=<image> -P check_divisions.cmake
#
# A 32-bit Cortex-M has no 64-bit divide instruction (a Cortex-M0+ has none at all): `a / b` on
# 64-bit operands calls libgcc's __aeabi_uldivmod or __aeabi_ldivmod, hundreds of cycles on a
# small core and 700 bytes of flash. iecoop divides an LTIME by a constant through its
# reciprocal and by a run-time value without the routine (iecoop/detail/constant_division.hpp;
# docs/embedded.md, "64-bit divisions"), so no image of iecoop's needs it. The disassembly is
# the evidence: every function that calls one of the routines is listed (but the routines
# themselves). The `leaky_division` image proves the check can fail (expect_check_fails.cmake).
cmake_minimum_required(VERSION 3.25)
if(NOT DEFINED OBJDUMP OR NOT DEFINED ELF)
  message(FATAL_ERROR "usage: cmake -DOBJDUMP=<objdump> -DELF=<image> -P check_divisions.cmake")
endif()

execute_process(COMMAND ${OBJDUMP} -d --demangle ${ELF} OUTPUT_VARIABLE listing RESULT_VARIABLE status)
if(NOT status EQUAL 0)
  message(FATAL_ERROR "${OBJDUMP} failed on ${ELF} (status ${status})")
endif()

set(division_routines "__aeabi_uldivmod|__aeabi_ldivmod|__udivmoddi4|__divmoddi4|__udivdi3|__divdi3|__umoddi3|__moddi3")
set(allowed "^(${division_routines})$")

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
  message(FATAL_ERROR "${ELF} divides 64-bit integers with libgcc's routine:\n  ${found}\n"
                      "divide by a constant (detail::divide_by<D>) or with detail::divide_u64 "
                      "(iecoop/detail/constant_division.hpp), or in 32 bits")
endif()
message("${ELF}: no 64-bit division routine called")
