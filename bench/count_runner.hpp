// The main() of the instruction-count programs (count_main.cpp, testing_count.cpp,
// util_count.cpp): runs the kernel named on the command line n times, for bench/callgrind.sh, or
// lists the kernels; and keep(), which their kernels share.
//
//   <program> <kernel> <n>      <program> --list
#pragma once

#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <type_traits>

namespace bench {

/// Keeps `value` in memory, as the compiler must assume that it was read and written here (a
/// block instance stays in memory between calls, as it does in a program).
template <class T>
inline void keep(T& value) {
  asm volatile("" : : "r,m"(&value) : "memory");
}

/// `kernels`: an array of {const char* name; R (*run)(std::uint64_t n);}. A kernel that returns
/// a value makes the program's status depend on it, so that the optimiser keeps every cycle.
template <class Kernel, std::size_t N>
int run_count_main(int argc, char** argv, const Kernel (&kernels)[N], const char* program) {
  if (argc == 2 && std::strcmp(argv[1], "--list") == 0) {
    for (const Kernel& k : kernels) std::printf("%s\n", k.name);
    return 0;
  }
  if (argc != 3) {
    std::fprintf(stderr, "usage: %s <kernel> <n> | --list\n", program);
    return 2;
  }
  for (const Kernel& k : kernels) {
    if (std::strcmp(argv[1], k.name) == 0) {
      const std::uint64_t n = std::strtoull(argv[2], nullptr, 10);
      if constexpr (std::is_void_v<decltype(k.run(n))>) {
        k.run(n);
        return 0;
      } else {
        return k.run(n) == 0xFFFFFFFFU ? 1 : 0;
      }
    }
  }
  std::fprintf(stderr, "%s: no kernel %s (see --list)\n", program, argv[1]);
  return 2;
}

}  // namespace bench
