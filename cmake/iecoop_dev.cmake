# Build settings for iecoop's own targets (tests, examples, benchmarks). None of this
# reaches users of iecoop::iecoop: the library target itself carries no flags.

add_library(iecoop_warnings INTERFACE)
if(CMAKE_CXX_COMPILER_ID MATCHES "GNU|Clang")
  target_compile_options(iecoop_warnings INTERFACE -Wall -Wextra -Wpedantic
    -Wshadow -Wconversion -Wsign-conversion -Wold-style-cast
    $<$<BOOL:${IECOOP_WERROR}>:-Werror>)
elseif(MSVC)
  target_compile_options(iecoop_warnings INTERFACE /W4 /permissive- $<$<BOOL:${IECOOP_WERROR}>:/WX>)
endif()

add_library(iecoop_sanitizers INTERFACE)
if(IECOOP_SANITIZE)
  list(JOIN IECOOP_SANITIZE "," _iecoop_sanitizers)
  target_compile_options(iecoop_sanitizers INTERFACE
    -fsanitize=${_iecoop_sanitizers} -fno-sanitize-recover=all -fno-omit-frame-pointer)
  target_link_options(iecoop_sanitizers INTERFACE -fsanitize=${_iecoop_sanitizers})
endif()

# iecoop_dev_target(<target>): our strict warnings and the configured sanitizers.
function(iecoop_dev_target target)
  target_link_libraries(${target} PRIVATE iecoop::iecoop iecoop_warnings iecoop_sanitizers)
endfunction()

# Flags that mimic an embedded build, for the targets that must prove the headers need
# neither exceptions nor RTTI.
set(IECOOP_EMBEDDED_FLAGS -fno-exceptions -fno-rtti)
