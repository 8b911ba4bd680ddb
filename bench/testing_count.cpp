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

#include "count_runner.hpp"
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

int main(int argc, char** argv) { return bench::run_count_main(argc, argv, all_kernels, "iecoop_bench_testing_count"); }
