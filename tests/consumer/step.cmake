# Included by the consumer scripts (install_recipe.cmake, packages.cmake, pkg_config.cmake,
# coverage.cmake): step(<command>...) runs a command, prints what it printed, stops the script
# with "<STEP_PREFIX>: failed: <command>" if it fails, and leaves its standard output in
# step_output. A script may set step_directory to `WORKING_DIRECTORY <dir>`.
function(step)
  execute_process(COMMAND ${ARGN} ${step_directory} RESULT_VARIABLE result OUTPUT_VARIABLE out ERROR_VARIABLE err)
  message("${out}${err}")
  if(NOT result EQUAL 0)
    message(FATAL_ERROR "${STEP_PREFIX}: failed: ${ARGN}")
  endif()
  set(step_output "${out}" PARENT_SCOPE)
endfunction()
