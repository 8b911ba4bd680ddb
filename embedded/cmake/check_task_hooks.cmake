# Fails if a firmware image links a task hook that none of its tasks needs:
#
#   cmake -DNM=<arm-none-eabi-nm> -DELF=<image> -P check_task_hooks.cmake
#
# The freewheeling pause (64-bit divisions) and the watchdog check are reached only through
# the hooks task<...>{...} sets for the tasks that need them (task_settings::hooks): an image
# whose tasks are all cyclic without a watchdog must link neither — 430 bytes of the scheduler
# example's flash on the Cortex-M3. The symbol table is the evidence (a hook's address is taken,
# so it is never inlined away); the `leaky_task_hooks` image, with a freewheeling task and a
# watchdog, proves the check can fail.
cmake_minimum_required(VERSION 3.25)
if(NOT DEFINED NM OR NOT DEFINED ELF)
  message(FATAL_ERROR "usage: cmake -DNM=<nm> -DELF=<image> -P check_task_hooks.cmake")
endif()

execute_process(COMMAND ${NM} --demangle ${ELF} OUTPUT_VARIABLE table RESULT_VARIABLE status)
if(NOT status EQUAL 0)
  message(FATAL_ERROR "${NM} failed on ${ELF} (status ${status})")
endif()

set(found "")
foreach(hook freewheeling_pause watchdog_fault report_watchdog_fault)
  if(table MATCHES "[A-Za-z] iecoop::detail::${hook}\\(")
    list(APPEND found "iecoop::detail::${hook}")
  endif()
endforeach()

if(found)
  list(JOIN found ", " listing)
  message(FATAL_ERROR "task hooks: ${ELF} links ${listing}, which only a freewheeling task or a watchdog needs")
endif()
message("${ELF}: no task hooks")
