# Fails if a firmware image links a task hook that none of its tasks needs:
#
#   cmake -DNM=<arm-none-eabi-nm> -DELF=<image> -P check_task_hooks.cmake
#
# The freewheeling pause (64-bit divisions), the watchdog check and what the end of a cycle does
# with them (end_hooked_cycle) are reached only through the hooks task<...>{...} sets for the
# tasks that need them (task_settings::hooks): an image whose tasks are all cyclic without a
# watchdog must link none of them — about 500 bytes of the scheduler example's flash on the
# Cortex-M3. The symbol table is the evidence (a hook's address is taken, so it is never inlined
# away); the `leaky_task_hooks` image, with a freewheeling task and a watchdog, proves the check
# can fail.
cmake_minimum_required(VERSION 3.25)
set(check_usage "cmake -DNM=<arm-none-eabi-nm> -DELF=<image> -P check_task_hooks.cmake")
set(demangle ON)
include(${CMAKE_CURRENT_LIST_DIR}/symbol_names.cmake)

set(found "")
foreach(name IN LISTS symbol_names)
  # (end_hooked_cycle is a template: its name starts with its return type)
  if(name MATCHES "(^|[ ])iecoop::detail::(freewheeling_pause|watchdog_fault|report_watchdog_fault|end_hooked_cycle)[(<]")
    list(APPEND found "iecoop::detail::${CMAKE_MATCH_2}")
  endif()
endforeach()

if(found)
  list(REMOVE_DUPLICATES found)
  list(SORT found) # nm sorts by mangled name: the order differs from one image to another
  list(JOIN found ", " listing)
  message(FATAL_ERROR "task hooks: ${ELF} links ${listing}, which only a freewheeling task or a watchdog needs")
endif()
message("${ELF}: no task hooks")
