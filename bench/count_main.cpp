// Repeats one benchmark kernel n times, for instruction counts under callgrind
// (bench/callgrind.sh runs it twice with different n and divides the difference, so that
// start-up and the cross-check are not counted):
//
//   iecoop_bench_count <kernel> <n>       iecoop_bench_count --list
//
// Kernels: the workload's scans (workload.hpp), the micro-benchmarks' steps (kernels.hpp),
// the scheduler's task cycles (one iteration = 1 ms of simulated time) and the trace
// recorder's cycles (trace_programs.hpp: one iteration = the program and one sample; trace_none
// is the program alone).
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <memory>
#include <utility>

#include "count_runner.hpp"
#include "kernels.hpp"
#include "scheduler_programs.hpp"
#include "trace_programs.hpp"
#include "workload.hpp"

namespace {

// Makes the compiler assume that memory was read and written here.
inline void barrier() { asm volatile("" ::: "memory"); }
using bench::keep;

template <class Side>
void workload_scans(std::uint64_t n) {
  Side::reset();
  for (std::uint64_t k = 0; k < n; ++k) Side::scan(static_cast<std::uint32_t>(k));
}
struct iecoop_scan {
  static void reset() { workload::iecoop_side::reset(); }
  static void scan(std::uint32_t k) { workload::iecoop_side::scan(k); }
};
struct handwritten_scan {
  static void reset() { workload::handwritten_side::reset(); }
  static void scan(std::uint32_t k) { workload::handwritten_side::scan(k); }
};
struct minimal_scan {
  static void reset() { workload::minimal_side::reset(); }
  static void scan(std::uint32_t k) { workload::minimal_side::scan(k); }
};

template <class Object, class Step>
void repeat(std::uint64_t n, Step step) {
  Object object{};
  keep(object);  // in memory, as a block instance is
  for (std::uint64_t i = 0; i < n; ++i) {
    step(object);
    barrier();
  }
  keep(object);
}

template <std::size_t N>
void task_cycles(std::uint64_t n) {
  auto plc = scheduler_programs::tasks_of_empty_program(std::make_index_sequence<N>{});
  plc.start();
  for (std::uint64_t i = 0; i < n; ++i) plc.run_for(iecoop::LTIME(iecoop::TIME(1)));
}
template <std::size_t N>
void handwritten_task_cycles(std::uint64_t n) {
  scheduler_programs::handwritten_executive<N> executive;
  for (std::uint64_t i = 0; i < n; ++i) executive.run_for(1'000'000);
}

template <trace_programs::recording How>
void trace_cycles(std::uint64_t n) {
  auto traced = std::make_unique<trace_programs::traced_program>(How);
  for (std::uint64_t i = 0; i < n; ++i) {
    traced->run_cycle();
    barrier();
  }
  keep(*traced);
}

struct kernel {
  const char* name;
  void (*run)(std::uint64_t n);
};

using namespace kernels;
const kernel all_kernels[] = {
    {"workload_iecoop", workload_scans<iecoop_scan>},
    {"workload_handwritten", workload_scans<handwritten_scan>},
    {"workload_handwritten_minimal", workload_scans<minimal_scan>},
    {"property_iecoop", [](std::uint64_t n) { repeat<FB_Prop>(n, [](FB_Prop& fb) { property_iecoop(fb); }); }},
    {"property_handwritten",
     [](std::uint64_t n) { repeat<plain_prop>(n, [](plain_prop& s) { property_handwritten(s); }); }},
    {"method_iecoop", [](std::uint64_t n) { repeat<FB_Scale>(n, [](FB_Scale& fb) { (void)method_iecoop(fb); }); }},
    {"method_handwritten",
     [](std::uint64_t n) { repeat<plain_scale>(n, [](plain_scale& s) { (void)method_handwritten(s); }); }},
    {"fbcall_iecoop", [](std::uint64_t n) { repeat<FB_Add>(n, [](FB_Add& fb) { (void)fbcall_iecoop(fb, INT(1)); }); }},
    {"fbcall_handwritten",
     [](std::uint64_t n) { repeat<plain_add>(n, [](plain_add& s) { (void)fbcall_handwritten(s, INT(1)); }); }},
    {"interface_iecoop",
     [](std::uint64_t n) {
       FB_MathMen fb;
       itf<I_Math> ip = fb;
       for (std::uint64_t i = 0; i < n; ++i) {
         keep(ip);
         (void)interface_iecoop(ip);
       }
     }},
    {"interface_virtual",
     [](std::uint64_t n) {
       plain_math m;
       plain_math_base* b = &m;
       for (std::uint64_t i = 0; i < n; ++i) {
         keep(b);
         (void)interface_virtual(*b);
       }
     }},
    {"interface_direct",
     [](std::uint64_t n) {
       plain_math m;
       plain_math* p = &m;
       for (std::uint64_t i = 0; i < n; ++i) {
         keep(p);
         (void)interface_direct(*p);
       }
     }},
    {"array_index_checked",
     [](std::uint64_t n) { repeat<ring<array_check::bounds>>(n, array_index_iecoop<array_check::bounds>); }},
    {"array_index_unchecked",
     [](std::uint64_t n) { repeat<ring<array_check::none>>(n, array_index_iecoop<array_check::none>); }},
    {"array_index_handwritten", [](std::uint64_t n) { repeat<plain_ring>(n, array_index_handwritten); }},
    {"array_loop_checked",
     [](std::uint64_t n) { repeat<ring<array_check::bounds>>(n, array_loop_iecoop<array_check::bounds>); }},
    {"array_loop_unchecked",
     [](std::uint64_t n) { repeat<ring<array_check::none>>(n, array_loop_iecoop<array_check::none>); }},
    {"array_loop_handwritten", [](std::uint64_t n) { repeat<plain_ring>(n, array_loop_handwritten); }},
    {"task_cycle_1", task_cycles<1>},
    {"task_cycle_8", task_cycles<8>},
    {"task_cycle_32", task_cycles<32>},
    {"task_cycle_handwritten_1", handwritten_task_cycles<1>},
    {"task_cycle_handwritten_8", handwritten_task_cycles<8>},
    {"task_cycle_handwritten_32", handwritten_task_cycles<32>},
    {"trace_none", trace_cycles<trace_programs::recording::none>},
    {"trace_every_cycle", trace_cycles<trace_programs::recording::every_cycle>},
    {"trace_every_cycle_trigger_armed", trace_cycles<trace_programs::recording::every_cycle_trigger_armed>},
    {"trace_on_change", trace_cycles<trace_programs::recording::on_change>},
    {"trace_on_change_unchanged", trace_cycles<trace_programs::recording::on_change_unchanged>},
};

}  // namespace

int main(int argc, char** argv) { return bench::run_count_main(argc, argv, all_kernels, "iecoop_bench_count"); }
