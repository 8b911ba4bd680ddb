# Included by the consumer projects that take iecoop as a subproject (add_subdirectory,
# FetchContent): there iecoop builds none of its own parts and installs nothing.
foreach(target IN ITEMS iecoop_tests iecoop_demo iecoop_bench iecoop_replay iecoop_warnings iecoop_check)
  if(TARGET ${target})
    message(FATAL_ERROR "iecoop added its own target ${target} although it is not the top-level project")
  endif()
endforeach()
if(IECOOP_INSTALL)
  message(FATAL_ERROR "iecoop generates install rules although it is not the top-level project")
endif()
