// SPDX-License-Identifier: MIT
// iecoop/runtime/realtime.hpp — runs an application against the steady clock: the same tasks, the
// same programs, the same statistics as in simulation, but each task sleeps until it is due
// and its cycle time is measured, not modelled.
//
//     std::atomic<bool> stop_requested{false};      // set from a SIGINT handler, say
//     plc.start();
//     iecoop::realtime_runner runner{plc, {.fifo = true}};
//     runner.run(stop_requested);                  // returns when asked to stop
//     plc.task("Fast").statistics().max_jitter;    // measured
//
// All tasks run in the calling thread, one cycle at a time: when several are due, the highest
// priority goes first, and a cycle that is under way finishes before another starts (there
// is no preemption, so blocks and globals need no locks; a long low-priority cycle delays a
// high-priority one, which shows in its jitter). With `fifo`, the thread asks for
// SCHED_FIFO scheduling at the first run() and keeps it until the runner is destroyed (or
// release_scheduling() is called), so that a program running it in slices — run for a while,
// print, run again — never drops to an ordinary thread in between; with `lock_memory` it also
// locks the process's memory. Without the privilege it runs as an ordinary thread
// (fifo_active() tells). Destroy the runner in the thread that ran it. For Linux and other
// POSIX systems; not part of <iecoop/iecoop.hpp>.
#pragma once

#include <algorithm>
#include <atomic>
#include <cstdint>
#include <thread>

#include <iecoop/config.hpp>
#include <iecoop/detail/chrono.hpp>  // std::chrono's durations and clocks
#include <iecoop/runtime/application.hpp>
#include <iecoop/runtime/scheduler.hpp>
#include <iecoop/types/time.hpp>

#if defined(__linux__)
#include <sched.h>
#include <sys/mman.h>
#include <time.h>
#endif

#include <iecoop/detail/push_macros.hpp>

namespace iecoop {

/// How a realtime_runner runs.
struct realtime_options {
  bool fifo = false;          ///< ask for SCHED_FIFO at fifo_priority while run() runs
  int fifo_priority = 50;     ///< 1..99 (Linux)
  bool lock_memory = false;   ///< with fifo granted: mlockall, so that no page fault delays a cycle
  LTIME event_poll{1000000};  ///< how often event conditions are sampled when nothing else is due (1 ms)
  LTIME max_sleep{50000000};  ///< the longest sleep, so that a stop request is seen within it (50 ms)
};

/// Why realtime_runner::run returned.
enum class run_end : std::uint8_t {
  stop_requested,  ///< the stop flag was set
  time_elapsed,    ///< the duration given to run() has passed
  not_running,     ///< the application was not running, or a watchdog fault stopped it
};

/**
 * Runs an application's tasks in real time, in the calling thread. The application's clock
 * continues from where it was (simulated time before, if any), so now() keeps counting.
 */
template <class App>
class realtime_runner {
 public:
  explicit realtime_runner(App& app, realtime_options options = {}) noexcept : app_(app), options_(options) {}
  realtime_runner(const realtime_runner&) = delete;
  realtime_runner& operator=(const realtime_runner&) = delete;
  /// Gives the thread its scheduling policy from before the first run() back.
  ~realtime_runner() { release_scheduling(); }

  /// Runs until `stop` is set, `duration` of steady time has passed, or the application
  /// stops running. Call it again to go on: the application's clock follows the steady clock
  /// from the first call on (unless a simulation moved it in between), so a caller may run it
  /// in slices, printing in between, say: the time between two calls counts as time passed,
  /// and releases due in it are late (or, later than an interval, omitted) as on a busy PLC.
  run_end run(const std::atomic<bool>& stop, LTIME duration = LTIME::max()) {
    if (!scheduling_asked_) acquire_scheduling();
    return run_cycles(stop, duration);
  }

  /// TRUE while the runner holds SCHED_FIFO for its thread (asked for with options.fifo, and
  /// permitted): from the first run() until release_scheduling() or the runner's end.
  [[nodiscard]] bool fifo_active() const noexcept { return fifo_active_; }

  /// Gives the thread its scheduling policy from before the first run() back (the next run()
  /// asks for SCHED_FIFO again). Call it in the thread that ran the runner.
  void release_scheduling() noexcept {
#if defined(__linux__)
    if (fifo_active_) (void)sched_setscheduler(0, previous_policy_, &previous_param_);
#endif
    fifo_active_ = false;
    scheduling_asked_ = false;
  }

 private:
  // SCHED_FIFO from the first run() on, if asked for and permitted; the thread's previous
  // policy is kept for release_scheduling().
  void acquire_scheduling() noexcept {
    scheduling_asked_ = true;
    fifo_active_ = false;
#if defined(__linux__)
    if (!options_.fifo) return;
    previous_policy_ = sched_getscheduler(0);
    if (previous_policy_ < 0 || sched_getparam(0, &previous_param_) != 0) return;
    sched_param param{};
    param.sched_priority = options_.fifo_priority;
    fifo_active_ = sched_setscheduler(0, SCHED_FIFO, &param) == 0;
    if (fifo_active_ && options_.lock_memory) (void)mlockall(MCL_CURRENT | MCL_FUTURE);
#endif
  }

  run_end run_cycles(const std::atomic<bool>& stop, LTIME duration) {
    // The application's clock follows the steady clock from the first run() on; a run() that
    // continues where the last one ended (nothing simulated in between) keeps that mapping,
    // so the time spent between two calls counts as time passed.
    auto& tasks = app_.scheduler();
    if (!mapped_ || tasks.now() != last_now_) {
      origin_ = std::chrono::steady_clock::now();
      base_ = tasks.now();
      mapped_ = true;
    }
    const run_end end = run_mapped(tasks, stop, duration);
    last_now_ = tasks.now();
    return end;
  }

  template <class Scheduler>
  run_end run_mapped(Scheduler& tasks, const std::atomic<bool>& stop, LTIME duration) {
    tasks.advance_to(clock_now());
    const LTIME deadline = detail::add_saturated(tasks.now(), duration);
    tasks.finish_cycles();  // a cycle a simulation left under way ends now

    for (;;) {
      if (stop.load(std::memory_order_relaxed)) return run_end::stop_requested;
      if (tasks.state() != scheduler_state::running) return run_end::not_running;
      LTIME now = clock_now();
      if (now >= deadline) {
        tasks.advance_to(deadline);
        return run_end::time_elapsed;
      }
      tasks.advance_to(now);
      tasks.release_due();
      for (std::size_t next = tasks.pick(); next != Scheduler::no_task; next = tasks.pick()) {
        const LTIME start = clock_now();
        // Overloaded (cycles longer than their intervals), tasks are always due: look at the
        // stop flag and the deadline between cycles too.
        if (stop.load(std::memory_order_relaxed) || start >= deadline) break;
        tasks.advance_to(start);
        tasks.begin_cycle(next);
        tasks.advance_to(clock_now());
        tasks.end_cycle(next);
        tasks.release_due();
      }
      now = clock_now();
      LTIME wake = std::min(tasks.next_release(), std::min(deadline, detail::add_saturated(now, options_.max_sleep)));
      if (tasks.has_event_tasks()) wake = std::min(wake, detail::add_saturated(now, options_.event_poll));
      if (wake > now)
        sleep_until(origin_ + std::chrono::nanoseconds(static_cast<std::int64_t>((wake - base_).count())));
    }
  }

  static void sleep_until(std::chrono::steady_clock::time_point when) {
#if defined(__linux__)
    // libstdc++'s steady_clock is CLOCK_MONOTONIC: sleep to the absolute instant, so that
    // the time spent computing the sleep does not add up.
    const auto since_epoch = std::chrono::duration_cast<std::chrono::nanoseconds>(when.time_since_epoch()).count();
    timespec ts{};
    ts.tv_sec = static_cast<time_t>(since_epoch / 1000000000);
    ts.tv_nsec = static_cast<long>(since_epoch % 1000000000);
    // A signal interrupts the sleep (EINTR): run() then looks at the stop flag and sleeps again.
    (void)clock_nanosleep(CLOCK_MONOTONIC, TIMER_ABSTIME, &ts, nullptr);
#else
    std::this_thread::sleep_until(when);
#endif
  }

  // The application's time now: base_ plus the steady time since origin_.
  [[nodiscard]] LTIME clock_now() const noexcept {
    const auto elapsed =
        std::chrono::duration_cast<std::chrono::nanoseconds>(std::chrono::steady_clock::now() - origin_);
    return base_ + LTIME::from_ticks(static_cast<std::uint64_t>(elapsed.count()));
  }

  App& app_;
  realtime_options options_;
  bool scheduling_asked_ = false;
  bool fifo_active_ = false;
#if defined(__linux__)
  int previous_policy_ = SCHED_OTHER;
  sched_param previous_param_{};
#endif
  bool mapped_ = false;
  std::chrono::steady_clock::time_point origin_{};
  LTIME base_{};
  LTIME last_now_{};
};

}  // namespace iecoop

#include <iecoop/detail/pop_macros.hpp>
