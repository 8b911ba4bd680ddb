# The C++ blocks of a Markdown page as one source file, so that a page's worked example also runs
# as a program (docs/testing.md -> docs/examples/testing_example.cpp, whose doctest cases are its
# tests). Reads the blocks as the docs' snippet check does (cmake/doc_snippets.cmake: ```cpp and
# the C++ column of ```text st|cpp:<column>), in order; their leading #include lines go to the
# top, each once, then `using namespace iecoop;` (the snippets' prelude), then the blocks, one
# blank line between two.
#
#   cmake -DMARKDOWN=docs/testing.md -DOUTPUT=docs/examples/testing_example.cpp -P tools/doc_example.cmake
#   cmake -DMARKDOWN=... -DOUTPUT=... -DCHECK=ON -P tools/doc_example.cmake   fails if OUTPUT differs
cmake_minimum_required(VERSION 3.25)
include(${CMAKE_CURRENT_LIST_DIR}/../cmake/doc_snippets.cmake)

if(NOT DEFINED MARKDOWN OR NOT DEFINED OUTPUT)
  message(FATAL_ERROR "usage: cmake -DMARKDOWN=<page.md> -DOUTPUT=<file.cpp> [-DCHECK=ON] -P tools/doc_example.cmake")
endif()

_iecoop_ds_parse("${MARKDOWN}")
if(NOT _ds_errors STREQUAL "")
  list(JOIN _ds_errors "\n" text)
  _iecoop_ds_decode(text)
  message(FATAL_ERROR "${text}")
endif()

set(includes "")
set(blocks "")
foreach(i RANGE 1 ${_ds_count})
  if(_ds_count EQUAL 0 OR _ds_${i}_skip OR _ds_${i}_has_fails)
    continue()
  endif()
  _iecoop_ds_hoist("${MARKDOWN}" ${i})
  string(REGEX REPLACE "#line [^\n]*\n" "" hoisted "${_hoisted}")
  string(REPLACE "\n" ";" hoisted "${hoisted}")
  foreach(line IN LISTS hoisted)
    if(NOT line STREQUAL "" AND NOT line IN_LIST includes)
      list(APPEND includes "${line}")
    endif()
  endforeach()
  # The block without the lines its #includes left blank, nor blank lines at its ends, nor runs
  # of blank lines (a side-by-side block leaves one where only the ST has text).
  string(REGEX REPLACE "^[ \n]*\n" "" code "\n${_rest}")
  string(REGEX REPLACE "[ \n]+$" "" code "${code}")
  string(REGEX REPLACE "[ ]+\n" "\n" code "${code}")
  string(REGEX REPLACE "\n\n\n+" "\n\n" code "${code}")
  string(APPEND blocks "\n${code}\n")
endforeach()

# The header names both files from the repository's root, however they were given.
get_filename_component(root "${CMAKE_CURRENT_LIST_DIR}/.." ABSOLUTE)
get_filename_component(markdown_path "${MARKDOWN}" ABSOLUTE)
get_filename_component(output_path "${OUTPUT}" ABSOLUTE)
file(RELATIVE_PATH markdown_name "${root}" "${markdown_path}")
file(RELATIVE_PATH output_name "${root}" "${output_path}")
set(text "// Generated from ${markdown_name} by tools/doc_example.cmake: edit the page, then run\n")
string(APPEND text "//   cmake -DMARKDOWN=${markdown_name} -DOUTPUT=${output_name} -P tools/doc_example.cmake\n")
string(APPEND text "// The page's C++ blocks in order, as one program (its ST is in the page). Built with the test\n")
string(APPEND text "// kit's main(): `-DIECOOP_TESTING_MAIN`, or linked to iecoop::testing_main.\n")
list(GET includes 0 first)
string(APPEND text "${first}\n")
list(REMOVE_AT includes 0)
if(includes)
  list(JOIN includes "\n" rest)
  string(APPEND text "\n${rest}\n")
endif()
string(APPEND text "\nusing namespace iecoop;\n${blocks}")
_iecoop_ds_decode(text)

if(CHECK)
  file(READ "${OUTPUT}" current)
  if(NOT current STREQUAL text)
    message(FATAL_ERROR "${OUTPUT} is not ${MARKDOWN}'s C++ blocks; run\n"
                        "  cmake -DMARKDOWN=${MARKDOWN} -DOUTPUT=${OUTPUT} -P tools/doc_example.cmake")
  endif()
  message(STATUS "${OUTPUT}: ${MARKDOWN}'s C++ blocks, as it should be")
else()
  file(WRITE "${OUTPUT}" "${text}")
  message(STATUS "wrote ${OUTPUT} from ${MARKDOWN}")
endif()
