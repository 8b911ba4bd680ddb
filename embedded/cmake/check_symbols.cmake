# Fails if a linked firmware image contains heap, exception or RTTI machinery:
#
#   cmake -DNM=<arm-none-eabi-nm> -DELF=<image> -P check_symbols.cmake
#
# The symbol table is the evidence: whatever the sources look like, a heap needs malloc and
# _sbrk, `new` needs operator new, a throw needs __cxa_allocate_exception and __cxa_throw,
# and RTTI needs typeinfo objects. Defined and undefined symbols both count. The build
# links without a system-call layer, so most of these already fail the link; this check is
# the second line, and the `leaky` images prove that it can fail.
cmake_minimum_required(VERSION 3.25)
set(check_usage "cmake -DNM=<arm-none-eabi-nm> -DELF=<image> -P check_symbols.cmake")
set(demangle ON)
include(${CMAKE_CURRENT_LIST_DIR}/symbol_names.cmake)

# C names must match exactly; demangled C++ names by their start.
set(heap_names malloc _malloc_r calloc _calloc_r realloc _realloc_r free _free_r _sbrk _sbrk_r)
set(exception_names __cxa_allocate_exception __cxa_throw __cxa_rethrow __cxa_begin_catch
                    __cxa_end_catch __gxx_personality_v0 _Unwind_RaiseException)
set(cxx_prefixes "operator new" "operator delete" "typeinfo for " "typeinfo name for " "__cxxabiv1::"
                 "vtable for __cxxabiv1::")

set(found "")
foreach(name IN LISTS symbol_names)
  if(name IN_LIST heap_names)
    list(APPEND found "heap: ${name}")
  elseif(name IN_LIST exception_names)
    list(APPEND found "exceptions: ${name}")
  else()
    foreach(prefix IN LISTS cxx_prefixes)
      string(FIND "${name}" "${prefix}" at)
      if(at EQUAL 0)
        if(prefix MATCHES "^operator")
          list(APPEND found "heap: ${name}")
        else()
          list(APPEND found "RTTI: ${name}")
        endif()
        break()
      endif()
    endforeach()
  endif()
endforeach()

if(found)
  list(REMOVE_DUPLICATES found)
  list(JOIN found "\n  " listing)
  message(FATAL_ERROR "${ELF} links forbidden machinery:\n  ${listing}")
endif()
message("${ELF}: no heap, no exceptions, no RTTI")
