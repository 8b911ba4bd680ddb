# Runs a firmware image, for the test scripts (run_firmware.cmake, check_trace_vcd.cmake):
# included by a `cmake -P` script that has ELF, TIMEOUT and, for the target, QEMU and MACHINE.
# Sets `output` (stdout), `errors` (stderr) and `status` (the exit status, or why it failed).
#
# With QEMU, the image runs on the board with semihosting (its text arrives on stdout, its
# exit status becomes QEMU's); without, ELF is a host executable (the host twin of the same
# example).
if(QEMU)
  # -display/-monitor/-serial none: no window, and no device claims the terminal (CI has none).
  # target=native: QEMU serves semihosting itself; without it the first request faults.
  set(firmware_command ${QEMU} -M ${MACHINE} -display none -monitor none -serial none
                       -semihosting-config enable=on,target=native -kernel ${ELF})
else()
  set(firmware_command ${ELF})
endif()
execute_process(COMMAND ${firmware_command}
  OUTPUT_VARIABLE output
  ERROR_VARIABLE errors
  RESULT_VARIABLE status
  TIMEOUT ${TIMEOUT})
