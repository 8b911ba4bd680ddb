# cmake -DINCLUDE_DIR=<dir> -P check_layering.cmake
# Checks that iecoop's headers include only downwards (docs/design.md, "The headers follow
# the parts of IEC 61131-3, in layers"):
#   config.hpp, fault.hpp            1  (used by every layer, as are detail/ headers)
#   types/                           2
#   pou/                             3
#   standard/                        4
#   io/                              5
#   runtime/                         6
#   trace/                           7  (recorder, writers, watch list: they observe the runtime)
#   iecoop.hpp, trace.hpp, fmt.hpp,  8  (the umbrella and the integrations)
#   ostream.hpp
# A detail/ header is shared machinery: it takes the layer of the highest header it includes
# (at least 1), and may build on types/ but on nothing above.
cmake_minimum_required(VERSION 3.25)
if(NOT INCLUDE_DIR)
  message(FATAL_ERROR "usage: cmake -DINCLUDE_DIR=<dir> -P check_layering.cmake")
endif()

get_filename_component(INCLUDE_DIR "${INCLUDE_DIR}" ABSOLUTE)
set(rank_types 2)
set(rank_pou 3)
set(rank_standard 4)
set(rank_io 5)
set(rank_runtime 6)
set(rank_trace 7)
set(detail_ceiling 2)

file(GLOB_RECURSE headers RELATIVE ${INCLUDE_DIR} ${INCLUDE_DIR}/iecoop/*.hpp)

# The iecoop headers a header includes, relative to INCLUDE_DIR.
function(includes_of header out)
  file(STRINGS ${INCLUDE_DIR}/${header} lines REGEX "^#include <iecoop/")
  set(result)
  foreach(line IN LISTS lines)
    string(REGEX REPLACE "^#include <([^>]+)>.*$" "\\1" target "${line}")
    list(APPEND result ${target})
  endforeach()
  set(${out} ${result} PARENT_SCOPE)
endfunction()

# The layer of a header outside detail/.
function(folder_rank header out)
  if(header MATCHES "^iecoop/([a-z_]+)/")
    set(${out} ${rank_${CMAKE_MATCH_1}} PARENT_SCOPE)
  elseif(header MATCHES "^iecoop/(config|fault)\\.hpp$")
    set(${out} 1 PARENT_SCOPE)
  else()
    set(${out} 8 PARENT_SCOPE)
  endif()
endfunction()

# detail/ headers: their rank from what they include (iterated to a fixed point).
set(detail_headers ${headers})
list(FILTER detail_headers INCLUDE REGEX "^iecoop/detail/")
foreach(header IN LISTS detail_headers)
  set(rank_of_${header} 1)
endforeach()
set(changed TRUE)
while(changed)
  set(changed FALSE)
  foreach(header IN LISTS detail_headers)
    includes_of(${header} targets)
    foreach(target IN LISTS targets)
      if(target MATCHES "^iecoop/detail/")
        set(r ${rank_of_${target}})
      else()
        folder_rank(${target} r)
      endif()
      if(r GREATER rank_of_${header})
        set(rank_of_${header} ${r})
        set(changed TRUE)
      endif()
    endforeach()
  endforeach()
endwhile()

set(violations 0)
foreach(header IN LISTS headers)
  if(header MATCHES "^iecoop/detail/")
    if(rank_of_${header} GREATER detail_ceiling)
      message(SEND_ERROR "iecoop: ${header} is shared machinery (detail/) but builds on a layer above types/; "
                         "move it into the layer it serves, or take out that include")
      math(EXPR violations "${violations} + 1")
    endif()
    continue()
  endif()
  folder_rank(${header} own)
  includes_of(${header} targets)
  foreach(target IN LISTS targets)
    if(NOT EXISTS ${INCLUDE_DIR}/${target})
      message(SEND_ERROR "iecoop: ${header} includes <${target}>, which does not exist")
      math(EXPR violations "${violations} + 1")
      continue()
    endif()
    if(target MATCHES "^iecoop/detail/")
      set(r ${rank_of_${target}})
    else()
      folder_rank(${target} r)
    endif()
    if(r GREATER own)
      message(SEND_ERROR "iecoop: ${header} (layer ${own}) includes <${target}> (layer ${r}), a layer above it; "
                         "a header may include only its own layer and those below (docs/design.md)")
      math(EXPR violations "${violations} + 1")
    endif()
  endforeach()
endforeach()
list(LENGTH headers count)
if(violations EQUAL 0)
  message(STATUS "iecoop: ${count} headers, every include points to the same layer or below")
endif()
