# Build settings for iecoop's own targets (tests, examples, benchmarks). None of this
# reaches users of iecoop::iecoop: the library target itself carries no flags.

# iecoop_warnings: our strict warnings. IECOOP_WARNING_FLAGS holds the same flags (GCC and Clang,
# without -Werror) for compilers that scripts run: the docs' snippets (cmake/doc_snippets.cmake).
add_library(iecoop_warnings INTERFACE)
set(IECOOP_WARNING_FLAGS "")
if(CMAKE_CXX_COMPILER_ID MATCHES "GNU|Clang")
  set(IECOOP_WARNING_FLAGS -Wall -Wextra -Wpedantic -Wshadow -Wconversion -Wsign-conversion -Wold-style-cast)
  target_compile_options(iecoop_warnings INTERFACE ${IECOOP_WARNING_FLAGS}
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
