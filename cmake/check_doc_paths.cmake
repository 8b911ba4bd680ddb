# cmake -DSOURCE_DIR=<iecoop> -P check_doc_paths.cmake
# Every file a document names is in the repository (a user has only the repository): in
# README.md, DEVELOPERS.md, CHANGELOG.md and docs/*.md, each relative Markdown link's target
# and each `path` in backticks that starts with one of the tree's folders (bench/, cmake/,
# docs/, embedded/, examples/, include/, tests/, tools/, .ci/) or with ../ must exist (a
# pattern with * must match a file). And no file of the tree names the material outside it
# (../shared) that iecoop was developed from.
cmake_minimum_required(VERSION 3.25)
file(GLOB docs ${SOURCE_DIR}/docs/*.md)
set(documents ${SOURCE_DIR}/README.md ${SOURCE_DIR}/DEVELOPERS.md ${SOURCE_DIR}/CHANGELOG.md ${docs})
set(failures "")
set(checked 0)

# exists(<out> <path> <directory of the document>): the path, from the repository's root or
# from the document's folder, names something in the tree (a pattern: at least one file).
function(exists out path doc_dir)
  set(found FALSE)
  string(REGEX REPLACE "[#?].*$" "" path "${path}")  # a link's anchor
  foreach(base ${SOURCE_DIR} ${doc_dir})
    set(candidate ${base}/${path})
    set(matches)
    if(path MATCHES "\\*")
      file(GLOB matches ${candidate})
    elseif(EXISTS ${candidate})
      set(matches ${candidate})
    endif()
    foreach(match IN LISTS matches)  # in the tree, not beside it
      get_filename_component(match ${match} ABSOLUTE)
      string(FIND "${match}/" "${SOURCE_DIR}/" at)
      if(at EQUAL 0)
        set(found TRUE)
      endif()
    endforeach()
  endforeach()
  set(${out} ${found} PARENT_SCOPE)
endfunction()

foreach(document IN LISTS documents)
  get_filename_component(doc_dir ${document} DIRECTORY)
  file(RELATIVE_PATH name ${SOURCE_DIR} ${document})
  file(READ ${document} text)
  # Code blocks name build directories and a user's own files: only prose is checked.
  string(REGEX REPLACE "```[^`]*```" "" prose "${text}")
  # CMake's lists keep [...] together: the brackets become markers first.
  string(REPLACE "[" "<lb>" prose "${prose}")
  string(REPLACE "]" "<rb>" prose "${prose}")
  string(REGEX MATCHALL "<rb>\\([^); \t\n]+\\)" links "${prose}")
  string(REGEX MATCHALL "`[^`; \t\n]+`" quoted "${prose}")
  set(paths)
  foreach(link IN LISTS links)
    string(REGEX REPLACE "^<rb>\\((.*)\\)$" "\\1" target "${link}")
    if(NOT target MATCHES "^(https?:|mailto:|#)")
      list(APPEND paths "${target}")
    endif()
  endforeach()
  foreach(token IN LISTS quoted)
    string(REGEX REPLACE "^`(.*)`$" "\\1" token "${token}")
    if(token MATCHES "^(\\.\\./|(bench|cmake|docs|embedded|examples|include|tests|tools|\\.ci)/)"
       AND NOT token MATCHES "[<>{}$]|\\.\\.\\.")
      list(APPEND paths "${token}")
    endif()
  endforeach()
  foreach(path IN LISTS paths)
    math(EXPR checked "${checked} + 1")
    exists(found "${path}" ${doc_dir})
    if(NOT found)
      string(APPEND failures "${name}: names ${path}, which is not in the repository\n")
    endif()
  endforeach()
endforeach()

file(GLOB_RECURSE sources ${SOURCE_DIR}/include/*.hpp ${SOURCE_DIR}/examples/* ${SOURCE_DIR}/tools/*
     ${SOURCE_DIR}/tests/*.cpp ${SOURCE_DIR}/tests/*.hpp ${SOURCE_DIR}/bench/* ${SOURCE_DIR}/embedded/*)
foreach(file IN LISTS sources ITEMS ${documents})
  file(STRINGS ${file} lines REGEX "\\.\\./shared")
  if(lines)
    file(RELATIVE_PATH name ${SOURCE_DIR} ${file})
    string(APPEND failures "${name}: names ../shared, which a user of the repository does not have\n")
  endif()
endforeach()

if(failures)
  message(FATAL_ERROR "check_doc_paths:\n${failures}")
endif()
message("check_doc_paths: the ${checked} paths the documents name are in the repository")
