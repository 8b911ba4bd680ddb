# The firmware examples (embedded/examples/<name>.cpp, each with <name>.expected, its exact
# output) and the exit status each ends with: 0, but `fault`, which ends in its fault handler.
# Read by embedded/CMakeLists.txt (the images, run under QEMU) and by examples/CMakeLists.txt
# (the same sources built for the host).
set(IECOOP_FIRMWARE_EXAMPLES i_math_interface property_and_method timers_counters scheduler trace sfc_station process_image
                             pid_loop fault)
foreach(example IN LISTS IECOOP_FIRMWARE_EXAMPLES)
  set(IECOOP_FIRMWARE_STATUS_${example} 0)
endforeach()
set(IECOOP_FIRMWARE_STATUS_fault 2)  # firmware::exit_status::iecoop_fault
