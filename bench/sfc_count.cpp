// Repeats one of the SFC benchmark's kernels n times (sfc_programs.hpp), for instruction counts
// under callgrind: bench/callgrind.sh runs it twice with different n and divides the
// difference, so that start-up and the check below are not counted.
//
//   iecoop_bench_sfc_count <kernel> <n>      iecoop_bench_sfc_count --list
//   sh bench/callgrind.sh build/bench/iecoop_bench_sfc_count
//
// Kernels: sfc_chart (a scan of the 20-step chart, on the compiled engine), sfc_chart_general
// (on the general engine), sfc_handwritten (a scan of the switch-based twin), sfc_inputs (what
// the kernels spend on the clock, the inputs and the loop alone).
// Before any kernel runs, the two sides must produce the same outputs over
// sfc_programs::check_scans scans; the program fails if they do not.
#include <cstdint>
#include <cstdio>

#include "count_runner.hpp"
#include "sfc_programs.hpp"

namespace {

// The driver alone: the cycle clock and the inputs of each scan, into a bare record.
std::uint32_t inputs_only(std::uint64_t n) {
  sfc_programs::inputs sink{};
  for (std::uint64_t i = 0; i < n; ++i) {
    const auto k = static_cast<std::uint32_t>(i);
    sfc_programs::set_clock(k);
    sink = sfc_programs::inputs_at(k);
    sfc_programs::barrier();
  }
  return sink.START ? 1U : 0U;
}

struct kernel {
  const char* name;
  std::uint32_t (*run)(std::uint64_t n);
};

const kernel all_kernels[] = {
    {"sfc_chart", sfc_programs::chart_scans<sfc_programs::P_BATCH>},
    {"sfc_chart_general", sfc_programs::chart_scans<sfc_programs::P_BATCH_GENERAL>},
    {"sfc_handwritten", sfc_programs::hand_scans},
    {"sfc_inputs", inputs_only},
};

}  // namespace

int main(int argc, char** argv) {
  std::uint32_t sequences = 0;
  for (const std::uint32_t agreed : {sfc_programs::check<sfc_programs::P_BATCH>(sequences),
                                     sfc_programs::check<sfc_programs::P_BATCH_GENERAL>(sequences)}) {
    if (agreed != sfc_programs::check_scans) {
      std::fprintf(stderr, "iecoop_bench_sfc_count: the chart and the hand-written machine differ after scan %u\n",
                   agreed);
      return 1;
    }
  }
  return bench::run_count_main(argc, argv, all_kernels, "iecoop_bench_sfc_count");
}
