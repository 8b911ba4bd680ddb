# Feeds the VCD that a firmware example prints to a real VCD reader, GTKWave's: vcd2fst
# converts it to GTKWave's FST format and fst2vcd writes that back as VCD. The test passes only
# if the round trip keeps every signal (its scope, name, type and width), the timescale and
# every signal's values at every time, so that GTKWave reads the dump as the firmware meant it.
#
#   cmake -DELF=<image> [-DQEMU=<qemu-system-arm> -DMACHINE=<board>] -DWORK_DIR=<directory>
#         [-DVCD2FST=<vcd2fst> -DFST2VCD=<fst2vcd>] [-DTIMEOUT=<seconds>] -P check_trace_vcd.cmake
#
# The image runs as run_firmware.cmake runs it (firmware_command.cmake) and must end with
# status 0; the VCD is what it prints between the lines `--- begin trace.vcd` and
# `--- end trace.vcd`. WORK_DIR keeps the files: trace.vcd, trace.fst, roundtrip.vcd and, for
# a failure, the two canonical forms compared (trace.canonical, roundtrip.canonical).
#
# vcd2fst accepts nearly anything (a file of garbage gives an empty FST and status 0), which
# is why the values are compared, not only the status. Reals are compared by their decimal
# digits and exponent: fst2vcd prints them with 16 significant digits, so an LREAL that needs
# 17 would differ.
cmake_minimum_required(VERSION 3.25)
if(NOT DEFINED ELF OR NOT DEFINED WORK_DIR)
  message(FATAL_ERROR "usage: cmake -DELF=<image> [-DQEMU=... -DMACHINE=...] -DWORK_DIR=<directory> "
                      "-P check_trace_vcd.cmake")
endif()
if(NOT DEFINED TIMEOUT)
  set(TIMEOUT 30)
endif()

# GTKWave's converters, looked for when the test runs (so that installing gtkwave after the
# configure is enough).
if(NOT VCD2FST)
  find_program(VCD2FST vcd2fst)
endif()
if(NOT FST2VCD)
  find_program(FST2VCD fst2vcd)
endif()
if(NOT VCD2FST OR NOT FST2VCD)
  message(FATAL_ERROR "vcd2fst and fst2vcd, GTKWave's VCD reader and writer, are not installed: install gtkwave "
                      "(apt-get install --no-install-recommends gtkwave; tools/test.sh does)")
endif()

# --- The firmware's output, and the VCD in it ----------------------------------------------
include(${CMAKE_CURRENT_LIST_DIR}/firmware_command.cmake)  # runs ELF: output, errors, status
if(NOT status STREQUAL "0")
  message(FATAL_ERROR "${ELF} ended with status '${status}', expected 0; it printed:\n${output}\n${errors}")
endif()
set(begin_marker "--- begin trace.vcd\n")
set(end_marker "--- end trace.vcd\n")
string(FIND "${output}" "${begin_marker}" begin_at)
string(FIND "${output}" "${end_marker}" end_at)
if(begin_at EQUAL -1 OR end_at EQUAL -1 OR end_at LESS begin_at)
  message(FATAL_ERROR "${ELF} printed no VCD between '--- begin trace.vcd' and '--- end trace.vcd':\n${output}")
endif()
string(LENGTH "${begin_marker}" marker_length)
math(EXPR vcd_at "${begin_at} + ${marker_length}")
math(EXPR vcd_length "${end_at} - ${vcd_at}")
string(SUBSTRING "${output}" ${vcd_at} ${vcd_length} vcd)

file(MAKE_DIRECTORY ${WORK_DIR})
set(vcd_file ${WORK_DIR}/trace.vcd)
set(fst_file ${WORK_DIR}/trace.fst)
file(REMOVE ${fst_file} ${WORK_DIR}/roundtrip.vcd ${WORK_DIR}/trace.canonical ${WORK_DIR}/roundtrip.canonical)
file(WRITE ${vcd_file} "${vcd}")

# --- GTKWave's round trip -----------------------------------------------------------------
execute_process(COMMAND ${VCD2FST} ${vcd_file} ${fst_file}
  OUTPUT_VARIABLE converted ERROR_VARIABLE convert_errors RESULT_VARIABLE convert_status TIMEOUT ${TIMEOUT})
if(NOT convert_status STREQUAL "0" OR NOT EXISTS ${fst_file})
  message(FATAL_ERROR "vcd2fst rejected ${vcd_file} (status '${convert_status}'):\n${converted}${convert_errors}")
endif()
execute_process(COMMAND ${FST2VCD} ${fst_file}
  OUTPUT_VARIABLE roundtrip ERROR_VARIABLE roundtrip_errors RESULT_VARIABLE roundtrip_status TIMEOUT ${TIMEOUT})
file(WRITE ${WORK_DIR}/roundtrip.vcd "${roundtrip}")
if(NOT roundtrip_status STREQUAL "0")
  message(FATAL_ERROR "fst2vcd could not read the FST that vcd2fst made of ${vcd_file} (status "
                      "'${roundtrip_status}'):\n${roundtrip_errors}")
endif()

# --- Both VCDs in a canonical form --------------------------------------------------------
# real_canonical(<text> <out-var>): a real's decimal text as `r<sign>0.<digits>e<exponent>`,
# so that `0.000000001` and fst2vcd's `1e-09` compare equal (nan and inf as they are).
function(real_canonical text out_var)
  if(NOT text MATCHES "^([+-]?)([0-9]*)[.]?([0-9]*)([eE]([+-]?[0-9]+))?$")
    string(TOLOWER "r${text}" text)
    set(${out_var} "${text}" PARENT_SCOPE)
    return()
  endif()
  set(sign "${CMAKE_MATCH_1}")
  set(digits "${CMAKE_MATCH_2}${CMAKE_MATCH_3}")
  string(LENGTH "${CMAKE_MATCH_2}" point)
  set(exponent 0)
  if(NOT "${CMAKE_MATCH_5}" STREQUAL "")
    set(exponent "${CMAKE_MATCH_5}")
  endif()
  string(REGEX REPLACE "^[+]" "" exponent "${exponent}")
  math(EXPR point "${point} + ${exponent}")
  # Without the leading zeros (each moves the point), then without the trailing ones.
  string(LENGTH "${digits}" all)
  string(REGEX MATCH "[1-9].*$" digits "${digits}")
  string(LENGTH "${digits}" kept)
  math(EXPR point "${point} - (${all} - ${kept})")
  string(REGEX MATCH "^.*[1-9]" digits "${digits}")
  if(sign STREQUAL "+" OR digits STREQUAL "")
    set(sign "")
  endif()
  if(digits STREQUAL "")
    set(${out_var} "r0" PARENT_SCOPE)
  else()
    set(${out_var} "r${sign}0.${digits}e${point}" PARENT_SCOPE)
  endif()
endfunction()

# vcd_canonical(<text> <out-var> <signal-count-var>): the timescale, then one line per signal,
# sorted by name: `<scope.path.name> <type> <width>: <time>=<value> ...`, with a value listed
# only where it changes. Identifier codes, the order of the declarations and of the changes at
# one time, and leading zeros of vectors do not matter; vcd2fst and fst2vcd may change them.
function(vcd_canonical text out_var count_var)
  # One list element per line: first the characters that CMake lists treat specially (all of
  # them may be identifier codes of a VCD).
  string(REPLACE "\\" "<bs>" text "${text}")
  string(REPLACE ";" "<sc>" text "${text}")
  string(REPLACE "[" "<lb>" text "${text}")
  string(REPLACE "]" "<rb>" text "${text}")
  string(REPLACE "\r" "" text "${text}")
  string(REPLACE "\n" ";" lines "${text}")

  set(scopes "")
  set(ids "")
  set(timescale "")
  set(block "")  # a $keyword ... $end block over several lines ($date, $version, $timescale, $comment)
  set(in_values FALSE)
  set(time "")
  foreach(line IN LISTS lines)
    string(STRIP "${line}" line)
    if(line STREQUAL "")
      continue()
    endif()
    if(NOT block STREQUAL "")
      string(APPEND block " ${line}")
      if(NOT line MATCHES "\\$end$")
        continue()
      endif()
      set(line "${block}")
      set(block "")
    elseif(line MATCHES "^\\$(date|version|timescale|comment)" AND NOT line MATCHES "\\$end$")
      set(block "${line}")
      continue()
    endif()

    if(line MATCHES "^\\$timescale(.*)\\$end$")
      string(REGEX REPLACE "[ \t]" "" timescale "${CMAKE_MATCH_1}")
    elseif(line MATCHES "^\\$(date|version|comment)")
      # nothing to compare
    elseif(line MATCHES "^\\$scope +[^ ]+ +([^ ]+) +\\$end$")
      list(APPEND scopes "${CMAKE_MATCH_1}")
    elseif(line MATCHES "^\\$upscope +\\$end$")
      list(POP_BACK scopes)
    elseif(line MATCHES "^\\$var +([^ ]+) +([0-9]+) +([^ ]+) +([^ ]+)")
      set(type "${CMAKE_MATCH_1}")
      set(width "${CMAKE_MATCH_2}")
      set(id "${CMAKE_MATCH_3}")
      set(name "${CMAKE_MATCH_4}")
      list(JOIN scopes "." path)
      string(HEX "${id}" key)
      if(NOT DEFINED decl_${key})  # an alias of a signal declared before is the same signal
        list(APPEND ids "${key}")
        set(decl_${key} "${path}.${name} ${type} ${width}")
        set(history_${key} "")
        set(last_${key} "")
      endif()
    elseif(line MATCHES "^\\$enddefinitions")
      set(in_values TRUE)
    elseif(NOT in_values)
      message(FATAL_ERROR "a declaration the check does not know: '${line}'")
    elseif(line MATCHES "^#([0-9]+)$")
      set(time "${CMAKE_MATCH_1}")
    elseif(line MATCHES "^\\$(dumpvars|dumpall|dumpon|dumpoff|end)")
      # the changes inside are read like any other
    else()
      if(line MATCHES "^([01xzXZ])(.+)$")
        set(value "${CMAKE_MATCH_1}")
        set(id "${CMAKE_MATCH_2}")
      elseif(line MATCHES "^[bB]([01xzXZ]+) +(.+)$")
        set(id "${CMAKE_MATCH_2}")  # before the REGEX MATCH, which sets CMAKE_MATCH_<n> again
        # Without the leading zeros (not REGEX REPLACE "^0+": CMake applies its ^ again after
        # each replacement).
        string(REGEX MATCH "[^0].*$" value "${CMAKE_MATCH_1}")
        if(value STREQUAL "")
          set(value 0)
        endif()
      elseif(line MATCHES "^[rR]([^ ]+) +(.+)$")
        set(id "${CMAKE_MATCH_2}")
        real_canonical("${CMAKE_MATCH_1}" value)
      else()
        message(FATAL_ERROR "a value change the check cannot read: '${line}'")
      endif()
      string(TOLOWER "${value}" value)
      string(HEX "${id}" key)
      if(NOT DEFINED decl_${key})
        message(FATAL_ERROR "a value change of an undeclared signal: '${line}'")
      endif()
      if(time STREQUAL "")
        message(FATAL_ERROR "a value change before the first time: '${line}'")
      endif()
      if(NOT value STREQUAL last_${key})
        string(APPEND history_${key} " ${time}=${value}")
        set(last_${key} "${value}")
      endif()
    endif()
  endforeach()

  set(signals "")
  foreach(key IN LISTS ids)
    list(APPEND signals "${decl_${key}}:${history_${key}}")
  endforeach()
  list(SORT signals)
  list(LENGTH signals count)
  list(JOIN signals "\n" joined)
  set(${out_var} "timescale ${timescale}\n${joined}\n" PARENT_SCOPE)
  set(${count_var} ${count} PARENT_SCOPE)
endfunction()

vcd_canonical("${vcd}" original original_signals)
vcd_canonical("${roundtrip}" read_back read_back_signals)
if(original_signals EQUAL 0)
  message(FATAL_ERROR "${vcd_file} declares no signal")
endif()
if(NOT original STREQUAL read_back)
  file(WRITE ${WORK_DIR}/trace.canonical "${original}")
  file(WRITE ${WORK_DIR}/roundtrip.canonical "${read_back}")
  message(FATAL_ERROR "GTKWave reads ${vcd_file} differently from what it says: ${original_signals} signals "
                      "written, ${read_back_signals} read back (fst2vcd of vcd2fst's FST). Written:\n${original}\n"
                      "Read back:\n${read_back}\n(see ${WORK_DIR}/trace.canonical and roundtrip.canonical)")
endif()
message("${original}")
message("GTKWave's vcd2fst read all ${original_signals} signals of ${vcd_file}, and fst2vcd wrote them back with "
        "the same values at the same times")
