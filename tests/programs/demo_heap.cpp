// "The core never allocates after start-up" (DEVELOPERS.md), shown on the whole demo
// application: the programs, tasks and global variable lists of examples/conveyor.hpp (the
// demo's own, demo::make_conveyor()), run as the demo runs them. Every heap allocation is
// counted, phase by phase (with a trace recorder on task Fast, written as VCD, CSV and SVG):
// operator new in all its forms (new, new[], aligned, nothrow), replaced here; and the C heap's blocks (malloc, calloc,
// realloc, aligned_alloc, posix_memalign, and so those behind operator new), through AddressSanitizer's allocator hooks
// in a build with it, else by replacing malloc and its kin on glibc (which supports it and exports its own as
// __libc_malloc and kin), elsewhere not at all (the output says so).
//
// Before start() (static initialisation, the application's construction) and in the first
// start() allocations are reported but allowed; from the end of start() on every phase must
// count zero: the simulated scenario (21 s, the demo's script), save_retained() and stop()
// with a memory_storage, reset warm, cold and origin each followed by start() and a run,
// the real-time runner (300 ms of wall time in three slices, as the demo runs it), and a
// restart after stop(). The last two phases save to a file_storage: with --check-file-storage
// (test heap.demo_file_storage) they must count zero too, without it they are only reported.
//
//     iecoop_demo_heap [--check-file-storage] [--retain FILE]
//
// Exit status 0 when no checked phase allocated, 1 otherwise (the output names the phases).
// IECOOP_DEMO_HEAP_ABORT=1 in the environment aborts at the first allocation of a checked
// phase, so that a debugger shows where it comes from.
#include <array>
#include <atomic>
#include <cerrno>
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <new>

#include <iecoop/runtime/file_storage.hpp>
#include <iecoop/runtime/realtime.hpp>
#include <iecoop/trace.hpp>

#include <string_view>

#include "conveyor.hpp"

// ---------------------------------------------------------------------------------------
// Counting

namespace {

std::atomic<std::uint64_t> new_count{0};    // operator new, every form
std::atomic<std::uint64_t> block_count{0};  // heap blocks handed out by the C heap (0 if not counted)
std::atomic<bool> abort_on_allocation{false};

void count_new() noexcept {
  new_count.fetch_add(1, std::memory_order_relaxed);
  if (abort_on_allocation.load(std::memory_order_relaxed)) std::abort();
}

[[maybe_unused]] void count_block() noexcept {
  block_count.fetch_add(1, std::memory_order_relaxed);
  if (abort_on_allocation.load(std::memory_order_relaxed)) std::abort();
}

void* allocate(std::size_t size) noexcept { return std::malloc(size == 0 ? 1 : size); }

void* allocate_aligned(std::size_t size, std::align_val_t alignment) noexcept {
  const auto align = static_cast<std::size_t>(alignment);
  const std::size_t rounded = size == 0 ? align : (size + align - 1) / align * align;
  return std::aligned_alloc(align, rounded);
}

}  // namespace

void* operator new(std::size_t size) {
  count_new();
  if (void* p = allocate(size)) return p;
  throw std::bad_alloc();
}
void* operator new[](std::size_t size) {
  count_new();
  if (void* p = allocate(size)) return p;
  throw std::bad_alloc();
}
void* operator new(std::size_t size, const std::nothrow_t&) noexcept {
  count_new();
  return allocate(size);
}
void* operator new[](std::size_t size, const std::nothrow_t&) noexcept {
  count_new();
  return allocate(size);
}
void* operator new(std::size_t size, std::align_val_t alignment) {
  count_new();
  if (void* p = allocate_aligned(size, alignment)) return p;
  throw std::bad_alloc();
}
void* operator new[](std::size_t size, std::align_val_t alignment) {
  count_new();
  if (void* p = allocate_aligned(size, alignment)) return p;
  throw std::bad_alloc();
}
void* operator new(std::size_t size, std::align_val_t alignment, const std::nothrow_t&) noexcept {
  count_new();
  return allocate_aligned(size, alignment);
}
void* operator new[](std::size_t size, std::align_val_t alignment, const std::nothrow_t&) noexcept {
  count_new();
  return allocate_aligned(size, alignment);
}
void operator delete(void* p) noexcept { std::free(p); }
void operator delete[](void* p) noexcept { std::free(p); }
void operator delete(void* p, std::size_t) noexcept { std::free(p); }
void operator delete[](void* p, std::size_t) noexcept { std::free(p); }
void operator delete(void* p, const std::nothrow_t&) noexcept { std::free(p); }
void operator delete[](void* p, const std::nothrow_t&) noexcept { std::free(p); }
void operator delete(void* p, std::align_val_t) noexcept { std::free(p); }
void operator delete[](void* p, std::align_val_t) noexcept { std::free(p); }
void operator delete(void* p, std::size_t, std::align_val_t) noexcept { std::free(p); }
void operator delete[](void* p, std::size_t, std::align_val_t) noexcept { std::free(p); }
void operator delete(void* p, std::align_val_t, const std::nothrow_t&) noexcept { std::free(p); }
void operator delete[](void* p, std::align_val_t, const std::nothrow_t&) noexcept { std::free(p); }

// The C heap. With AddressSanitizer (GCC: __SANITIZE_ADDRESS__, Clang: __has_feature), its
// allocator calls hooks for every block; malloc itself is the sanitizer's and stays so.
#if defined(__SANITIZE_ADDRESS__)
#define IECOOP_DEMO_HEAP_ASAN 1
#elif defined(__has_feature)
#if __has_feature(address_sanitizer)
#define IECOOP_DEMO_HEAP_ASAN 1
#endif
#endif

#if defined(IECOOP_DEMO_HEAP_ASAN)
extern "C" int __sanitizer_install_malloc_and_free_hooks(void (*malloc_hook)(const volatile void*, std::size_t),
                                                         void (*free_hook)(const volatile void*));
namespace {
void on_sanitizer_malloc(const volatile void*, std::size_t) { count_block(); }
void on_sanitizer_free(const volatile void*) {}
const char* const block_counting = "C heap counted through AddressSanitizer's allocator hooks";
bool start_block_counting() {
  return __sanitizer_install_malloc_and_free_hooks(&on_sanitizer_malloc, &on_sanitizer_free) != 0;
}
}  // namespace
#elif defined(__GLIBC__)
// glibc lets a program replace malloc and its kin (its manual, "Replacing malloc"); these
// count and hand over to glibc's own allocator, which glibc, libstdc++ and every library use
// through them. free, malloc_usable_size and the rest stay glibc's: the blocks are its.
extern "C" {
void* __libc_malloc(std::size_t size) noexcept;
void* __libc_calloc(std::size_t count, std::size_t size) noexcept;
void* __libc_realloc(void* p, std::size_t size) noexcept;
void* __libc_memalign(std::size_t alignment, std::size_t size) noexcept;

void* malloc(std::size_t size) noexcept {
  count_block();
  return __libc_malloc(size);
}
void* calloc(std::size_t count, std::size_t size) noexcept {
  count_block();
  return __libc_calloc(count, size);
}
void* realloc(void* p, std::size_t size) noexcept {
  if (size > 0 || p == nullptr) count_block();  // realloc(p, 0) frees
  return __libc_realloc(p, size);
}
void* aligned_alloc(std::size_t alignment, std::size_t size) noexcept {
  count_block();
  return __libc_memalign(alignment, size);
}
int posix_memalign(void** out, std::size_t alignment, std::size_t size) noexcept {
  if (alignment < sizeof(void*) || (alignment & (alignment - 1)) != 0) return EINVAL;
  count_block();
  void* p = __libc_memalign(alignment, size);
  if (p == nullptr) return ENOMEM;
  *out = p;
  return 0;
}
}
namespace {
const char* const block_counting = "C heap counted by replacing glibc's malloc, calloc, realloc and aligned forms";
bool start_block_counting() { return true; }
}  // namespace
#else
namespace {
const char* const block_counting = "C heap NOT counted on this platform (operator new only)";
bool start_block_counting() { return true; }
}  // namespace
#endif

// ---------------------------------------------------------------------------------------
// Phases

namespace {

using namespace iecoop;

enum class rule : std::uint8_t {
  allowed,       // start-up: reported
  zero,          // after start(): must not allocate
  file_storage,  // must not allocate with --check-file-storage, reported without
};

struct counts {
  std::uint64_t news = 0;
  std::uint64_t blocks = 0;
  [[nodiscard]] bool any() const noexcept { return news > 0 || blocks > 0; }
};

counts now_counted() noexcept {
  return {new_count.load(std::memory_order_relaxed), block_count.load(std::memory_order_relaxed)};
}

bool check_file_storage = false;
bool abort_requested = false;
int failures = 0;
int unchecked_file_storage_allocations = 0;

unsigned faults = 0;
unsigned watchdog_faults = 0;
void count_fault(const fault_info& f) {
  ++faults;
  if (f.kind == fault_kind::watchdog) ++watchdog_faults;
}

[[nodiscard]] bool checked(rule r) noexcept {
  return r == rule::zero || (r == rule::file_storage && check_file_storage);
}

void report(const char* name, rule r, counts c) {
  const char* verdict = "ok";
  if (r == rule::allowed) {
    verdict = "allowed (start-up)";
  } else if (c.any() && checked(r)) {
    verdict = "ALLOCATED";
  } else if (c.any()) {
    verdict = "allocated (file_storage: not checked without --check-file-storage)";
  } else if (r == rule::file_storage && !check_file_storage) {
    verdict = "ok (file_storage: not checked without --check-file-storage)";
  }
  std::printf("  %-58s %8llu %8llu  %s\n", name, static_cast<unsigned long long>(c.news),
              static_cast<unsigned long long>(c.blocks), verdict);
  if (c.any() && checked(r)) {
    ++failures;
    std::printf("demo_heap: FAILED: phase \"%s\" allocated (operator new %llu, heap blocks %llu) after start-up\n",
                name, static_cast<unsigned long long>(c.news), static_cast<unsigned long long>(c.blocks));
  } else if (c.any() && r == rule::file_storage) {
    ++unchecked_file_storage_allocations;
  }
  std::fflush(stdout);
}

/// Runs `work` as one phase, counting its allocations, and reports them.
template <class Work>
void phase(const char* name, rule r, Work&& work) {
  const counts before = now_counted();
  abort_on_allocation.store(abort_requested && checked(r), std::memory_order_relaxed);
  work();
  abort_on_allocation.store(false, std::memory_order_relaxed);
  const counts after = now_counted();
  report(name, r, {after.news - before.news, after.blocks - before.blocks});
}

/// A check of the run itself (outside the phases): that the application did what the phases
/// claim to have measured.
void expect(bool condition, const char* what) {
  if (condition) return;
  ++failures;
  std::printf("demo_heap: FAILED: %s\n", what);
  std::fflush(stdout);
}

template <class App>
void drain_trace(App& plc) {
  // What demo.cpp's print_trace consumes, without printing.
  sim::TRACE_PRG& trace = plc.template get<sim::TRACE_PRG>();
  trace.read = trace.written;
  trace.lost = 0;
}

template <class App>
void run_simulated(App& plc, LTIME until) {
  while (plc.now() < until && plc.state() == application_state::running) {
    plc.run_for("LTIME#100ms"_iec);
    drain_trace(plc);
  }
}

template <class App>
std::uint64_t fast_cycles(App& plc) {
  return plc.task("Fast").statistics().cycles;
}

}  // namespace

int main(int argc, char** argv) {
  const char* retain_file = "iecoop_demo_heap.retain";
  for (int i = 1; i < argc; ++i) {
    if (std::strcmp(argv[i], "--check-file-storage") == 0) {
      check_file_storage = true;
    } else if (std::strcmp(argv[i], "--retain") == 0 && i + 1 < argc) {
      retain_file = argv[++i];
    } else {
      std::fprintf(stderr, "usage: iecoop_demo_heap [--check-file-storage] [--retain FILE]\n");
      return 2;
    }
  }
  const char* abort_setting = std::getenv("IECOOP_DEMO_HEAP_ABORT");
  abort_requested = abort_setting != nullptr && std::strcmp(abort_setting, "1") == 0;
  const bool blocks_counted = start_block_counting();
  set_fault_handler(&count_fault);

  std::printf("demo_heap: heap allocations of the demo application, phase by phase (%s%s)\n\n", block_counting,
              blocks_counted ? "" : "; the hooks could not be installed");
  std::printf("  %-58s %8s %8s\n", "phase", "new", "blocks");
  // Static initialisation, and main() up to here (with its first output, whose buffer stdio
  // allocates); under the sanitizer the C heap's blocks are counted from main() on.
  report("static initialisation, main()'s first output", rule::allowed, now_counted());

  counts before = now_counted();
  auto plc = demo::make_conveyor();  // the demo's application (conveyor.hpp)
  plc.connect(sim::field);
  memory_storage<decltype(plc)::retain_bytes> memory;
  plc.use_storage(memory);
  counts after = now_counted();
  report("make_conveyor(), connect(), use_storage(memory_storage)", rule::allowed,
         {after.news - before.news, after.blocks - before.blocks});

  // As the demo: start, the drive fitted, the execution times of the simulation.
  phase("start()", rule::allowed, [&] {
    plc.start();
    sim::fitted = plc.get<demo::GVL_Config>().eMotor;
    plc.task("Fast").model_execution_time(&sim::fast_cost);
    plc.task("Slow").model_execution_time(&sim::slow_cost);
  });
  expect(plc.state() == application_state::running, "start(): the application does not run");

  // From here on, nothing may allocate: the trace recorder (as the demo's --svg configures it)
  // neither when it is set up, nor when it samples, nor when it is written.
  static trace_recorder<1024 * 1024, 32> shift_trace;
  phase("a trace recorder set up and started on task Fast", rule::zero, [&] {
    const demo::IO_PRG& io = plc.get<demo::IO_PRG>();
    shift_trace.add_located("GVL_IO", plc.get<demo::GVL_IO>());
    shift_trace.add_pins("IO_PRG.fbConveyor.tJam", io.fbConveyor.tJam);
    shift_trace.add("IO_PRG.fbConveyor", "rSpeed", io.fbConveyor.rSpeed);
    shift_trace.add("GVL", "rSpeed", plc.get<demo::GVL>().rSpeed);
    shift_trace.set_mode(trace_mode::on_change);
    shift_trace.attach(plc.task("Fast"));
    shift_trace.start();
  });
  phase("the simulated scenario (21 s, as iecoop_demo), traced", rule::zero,
        [&] { run_simulated(plc, LTIME(sim::scenario_length)); });
  std::size_t trace_bytes = 0;
  phase("the trace written as VCD, CSV and SVG", rule::zero, [&] {
    shift_trace.stop();
    const auto count = [&](std::string_view text) { trace_bytes += text.size(); };
    write_vcd(shift_trace.view(), count);
    write_csv(shift_trace.view(), count);
    write_svg(shift_trace.view(), count);
    shift_trace.detach();
  });
  expect(shift_trace.size() > 10000 && shift_trace.overwritten() == 0 && trace_bytes > 500000,
         "the trace of the scenario is not the demo's (more than 10000 samples, none lost, written in full)");
  {
    const demo::SUPERVISION_PRG& s = plc.get<demo::SUPERVISION_PRG>();
    expect(fast_cycles(plc) == 21000 && s.udiParts == 19U && s.udiBatches == 2U && s.uiJams == 1U &&
               s.udiRejected == 2U && plc.get<demo::GVL>().wParts == 1U,
           "the scenario did not end as iecoop_demo's (21000 cycles of Fast; parts 19, batches 2, jams 1, rejected "
           "2, in the open batch 1)");
  }

  bool saved = false;
  phase("save_retained() to memory_storage", rule::zero, [&] { saved = plc.save_retained(); });
  expect(saved && memory.size() > 0, "save_retained() did not save to the memory_storage");

  struct reset_step {
    reset_kind kind;
    const char* reset;
    const char* start;
    const char* run;
    demo::E_Motor motor;
  };
  const reset_step resets[] = {
      {reset_kind::warm, "reset(warm)", "start() after reset(warm)", "2 s after reset(warm), VFD", demo::E_Motor::VFD},
      {reset_kind::cold, "reset(cold)", "start() after reset(cold)", "2 s after reset(cold), DOL", demo::E_Motor::DOL},
      {reset_kind::origin, "reset(origin)", "start() after reset(origin)", "2 s after reset(origin), VFD",
       demo::E_Motor::VFD},
  };
  for (const reset_step& step : resets) {
    phase(step.reset, rule::zero, [&] { plc.reset(step.kind); });
    expect(plc.state() == application_state::halted, "a reset did not leave the application halted");
    phase(step.start, rule::zero, [&] { plc.start(); });
    expect(plc.state() == application_state::running, "start() after a reset: the application does not run");
    phase(step.run, rule::zero, [&] {
      plc.get<demo::GVL_Config>().eMotor = step.motor;  // commissioning, as iecoop_demo --motor
      sim::fitted = step.motor;
      run_simulated(plc, plc.now() + "LTIME#2s"_iec);
    });
    expect(fast_cycles(plc) == 2000, "a run of 2 s after a reset did not run 2000 cycles of Fast");
  }
  expect(plc.get<demo::SUPERVISION_PRG>().udiParts < 19U, "reset(origin) kept the RETAIN counter udiParts");

  run_end ended = run_end::not_running;
  std::uint64_t cycles_before = fast_cycles(plc);
  phase("real-time runner, 300 ms in three slices", rule::zero, [&] {
    realtime_runner runner{plc};
    const std::atomic<bool> stop{false};
    for (int slice = 0; slice < 3; ++slice) {
      ended = runner.run(stop, "LTIME#100ms"_iec);
      drain_trace(plc);
      if (ended != run_end::time_elapsed) break;
    }
  });
  expect(fast_cycles(plc) > cycles_before, "the real-time runner ran no cycle of Fast");
  if (ended != run_end::time_elapsed) {
    // A loaded machine can trip the watchdog in real time: reported, not failed (the
    // phase ran cycles, which is what is counted).
    std::printf("  (the real-time runner ended early: %s)\n",
                ended == run_end::not_running ? "the application stopped running (watchdog)" : "stop requested");
  }

  phase("stop() with memory_storage", rule::zero, [&] { plc.stop(); });
  expect(plc.state() == application_state::stopped, "stop() did not stop the application");
  phase("start() again: a restart from the retain memory", rule::zero, [&] { plc.start(); });
  expect(plc.state() == application_state::running, "start() after stop(): the application does not run");
  cycles_before = fast_cycles(plc);
  phase("1 s after the restart", rule::zero, [&] { run_simulated(plc, plc.now() + "LTIME#1s"_iec); });
  expect(fast_cycles(plc) == cycles_before + 1000, "the run after the restart did not run 1000 cycles of Fast");

  // file_storage: RETAIN and PERSISTENT data in a file, as iecoop_demo --retain FILE.
  std::remove(retain_file);
  file_storage file{retain_file};
  plc.use_storage(file);
  phase("save_retained() to file_storage", rule::file_storage, [&] { saved = plc.save_retained(); });
  expect(saved, "save_retained() did not save to the file_storage");
  phase("stop() with file_storage", rule::file_storage, [&] { plc.stop(); });
  std::array<std::byte, decltype(plc)::retain_bytes> image{};
  expect(file.load(image) > 0, "stop() left no image in the file_storage's file");
  std::remove(retain_file);

  const unsigned other_faults = faults - watchdog_faults;
  expect(other_faults == 0, "a fault other than the watchdog's was reported");
  if (watchdog_faults > 0) std::printf("  (%u watchdog faults, in real time on a loaded machine)\n", watchdog_faults);

  std::printf("\n");
  if (unchecked_file_storage_allocations > 0) {
    std::printf(
        "demo_heap: note: file_storage allocated in %d phases (not checked here; "
        "--check-file-storage checks them)\n",
        unchecked_file_storage_allocations);
  }
  if (failures > 0) {
    std::printf("demo_heap: FAILED: %d failures above\n", failures);
    return 1;
  }
  std::printf("demo_heap: no allocation after start-up%s\n", check_file_storage ? ", file_storage included" : "");
  return 0;
}
