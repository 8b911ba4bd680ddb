// Runs one of the test kit's benchmark kernels n times (testing_programs.hpp), for instruction
// counts under callgrind: bench/callgrind.sh runs it twice with different n and divides the
// difference, so that start-up is not counted.
//
//   iecoop_bench_testing_count <kernel> <n>      iecoop_bench_testing_count --list
//   sh bench/callgrind.sh build/bench/iecoop_bench_testing_count
#define DOCTEST_CONFIG_IMPLEMENT  // doctest's code, which the kit calls, without doctest's main()

#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>

#include "testing_programs.hpp"

namespace {

struct kernel {
  const char* name;
  std::uint32_t (*run)(std::uint64_t n);
};

const kernel all_kernels[] = {
    {"kit_cycles", testing_programs::kit_cycles},
    {"hand_cycles", testing_programs::hand_cycles},
    {"kit_plc", testing_programs::kit_plc},
    {"app_run_for", testing_programs::app_run_for},
};

}  // namespace

int main(int argc, char** argv) {
  if (argc == 2 && std::strcmp(argv[1], "--list") == 0) {
    for (const kernel& k : all_kernels) std::printf("%s\n", k.name);
    return 0;
  }
  if (argc != 3) {
    std::fprintf(stderr, "usage: iecoop_bench_testing_count <kernel> <n> | --list\n");
    return 2;
  }
  for (const kernel& k : all_kernels) {
    if (std::strcmp(argv[1], k.name) == 0) {
      // The result depends on every cycle: the optimiser keeps them all.
      return k.run(std::strtoull(argv[2], nullptr, 10)) == 0xFFFFFFFFU ? 1 : 0;
    }
  }
  std::fprintf(stderr, "iecoop_bench_testing_count: no kernel %s (see --list)\n", argv[1]);
  return 2;
}
