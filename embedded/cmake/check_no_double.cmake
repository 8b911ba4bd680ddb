# Fails if a firmware image links the soft-float library's double-precision routines:
#
#   cmake -DNM=<arm-none-eabi-nm> -DELF=<image> -P check_no_double.cmake
#
# A core without a double-precision FPU (Cortex-M0+, M3, M4F, M33) computes a `double` in
# libgcc's routines: about 3 KB of flash for the first add, multiply and conversion. An
# example that computes in REAL only must need none of them: iecoop converts a REAL to an
# integer in float arithmetic (types/detail/float_to_int.hpp), where a conversion through
# double, or libgcc's own float to 64-bit integer (which goes through double), would bring
# them in. The symbol table is the evidence; the `leaky_double` image proves the check can fail.
cmake_minimum_required(VERSION 3.25)
set(check_usage "cmake -DNM=<arm-none-eabi-nm> -DELF=<image> -P check_no_double.cmake")
set(demangle OFF)
include(${CMAKE_CURRENT_LIST_DIR}/symbol_names.cmake)

set(found "")
foreach(name IN LISTS symbol_names)
  # __aeabi_dadd, __aeabi_dmul, __aeabi_dcmplt, __aeabi_d2iz, ...; __aeabi_f2d, __aeabi_i2d,
  # __aeabi_ul2d; and their libgcc names (__adddf3, __extendsfdf2, __floatsidf, __fixdfsi, ...).
  if(name MATCHES "^__aeabi_(d[a-z0-9]+|f2d|u?i2d|u?l2d)$" OR name MATCHES "^__[a-z]+df[23]?$"
     OR name MATCHES "^__[a-z]+dfsf2$" OR name MATCHES "^__(fix|fixuns)df[sd]i$")
    list(APPEND found "${name}")
  endif()
endforeach()

if(found)
  list(REMOVE_DUPLICATES found)
  list(JOIN found ", " listing)
  message(FATAL_ERROR "soft double: ${ELF} links the double-precision routines ${listing}")
endif()
message("${ELF}: no double-precision routines")
