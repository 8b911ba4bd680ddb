# The names in a linked firmware image's symbol table, for the image checks that include this
# file (check_symbols.cmake, check_no_double.cmake, check_task_hooks.cmake):
#
#   set(check_usage "cmake -DNM=<nm> -DELF=<image> -P <check>.cmake")
#   set(demangle ON)          # C++ names demangled (nm --demangle); OFF: as linked
#   include(${CMAKE_CURRENT_LIST_DIR}/symbol_names.cmake)
#   foreach(name IN LISTS symbol_names) ... endforeach()
#
# Defined and undefined symbols both count ("<address> <type> <name>" or "<spaces> U <name>").
if(NOT DEFINED NM OR NOT DEFINED ELF)
  message(FATAL_ERROR "usage: ${check_usage}")
endif()
set(nm_options "")
if(demangle)
  set(nm_options --demangle)
endif()
execute_process(COMMAND ${NM} ${nm_options} ${ELF} OUTPUT_VARIABLE table RESULT_VARIABLE status)
if(NOT status EQUAL 0)
  message(FATAL_ERROR "${NM} failed on ${ELF} (status ${status})")
endif()
string(REPLACE "\n" ";" lines "${table}")
set(symbol_names "")
foreach(line IN LISTS lines)
  if(line MATCHES "^[0-9a-fA-F ]* [A-Za-z] (.+)$")
    list(APPEND symbol_names "${CMAKE_MATCH_1}")
  endif()
endforeach()
