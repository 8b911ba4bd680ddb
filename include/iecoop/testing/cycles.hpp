// SPDX-License-Identifier: MIT
// iecoop/testing/cycles.hpp — testing one block or program without an application: the
// driver sets the cycle clock, calls it once per cycle, and moves the clock on.
//
//     TON tmr;
//     testing::cycles run{tmr, "T#10ms"_iec};   // tmr() every 10 ms of simulated time
//     tmr.IN = TRUE;  tmr.PT = "T#50ms"_iec;
//     run.step();                                // cycle 0 at T#0ms
//     run.advance("T#50ms"_iec);                 // cycles 1..5
//     CHECK(tmr.Q);
//
//     testing::cycles call{[&] { fb("xIn"_ = x, "iLimit"_ = 5); }, "T#1ms"_iec};   // a call with arguments
//
// Each cycle: the cycle clock is set to now(), forced values are written, the body runs,
// forced values are written again, now() moves on by the cycle time. A fault the body cannot
// go past (a call through an unassigned interface) ends the body's call; the next cycle calls
// it again. The body runs in a task of its own (current_task(), <iecoop/runtime/task_info.hpp>):
// "testing::cycles" (set_task_name() renames it), cyclic with the cycle time, priority 31, its
// cycles taking no time.
// IWYU pragma: private, include <iecoop/testing.hpp>
#pragma once

#include <concepts>
#include <cstdint>
#include <type_traits>

#include <iecoop/fault.hpp>
#include <iecoop/runtime/task.hpp>
#include <iecoop/runtime/task_info.hpp>
#include <iecoop/standard/cycle_clock.hpp>
#include <iecoop/standard/detail/duration_argument.hpp>
#include <iecoop/testing/driver.hpp>
#include <iecoop/testing/faults.hpp>
#include <iecoop/types/literals.hpp>
#include <iecoop/types/time.hpp>

#include <iecoop/detail/push_macros.hpp>

namespace iecoop::testing {

/// Cycles of `Body`: a block or program (held by reference, called as `body()`) or any
/// callable (held by value).
template <class Body>
class cycles : public driver<cycles<Body>> {
  static_assert(std::invocable<Body&>,
                "iecoop: testing::cycles calls a block, a program or a callable without arguments each cycle; give "
                "the block (its inputs set before step()) or a lambda that calls it with its inputs");

 public:
  /// Runs `body` once per `cycle_time`, the first cycle at `start` (the cycle clock's time).
  template <class B>
  explicit cycles(B&& body, iecoop::detail::duration_argument cycle_time = LTIME(TIME(10)),
                  iecoop::detail::duration_argument start = LTIME{})
      : body_(std::forward<B>(body)), cycle_time_(cycle_time), now_(start) {}

  /// The time of the next cycle.
  [[nodiscard]] LTIME now() const noexcept { return now_; }
  /// The number of cycles run.
  [[nodiscard]] std::uint64_t cycle() const noexcept { return cycle_; }
  [[nodiscard]] LTIME cycle_time() const noexcept { return cycle_time_; }
  [[nodiscard]] LTIME step_time() const noexcept { return cycle_time_; }
  /// Changes the cycle time from the next cycle on.
  void set_cycle_time(iecoop::detail::duration_argument cycle_time) noexcept { cycle_time_ = cycle_time; }
  /// Sets the time of the next cycle (a replay table's time_ms); time may also jump back.
  void set_now(iecoop::detail::duration_argument now) noexcept { now_ = now; }

  /// n cycles (the drivers' step() and friends call this).
  void run_cycles(std::uint64_t n) {
    using task_driver = iecoop::detail::task_info_driver;
    for (std::uint64_t i = 0; i < n; ++i) {
      cycle_clock::set(now_);
      task_driver::configure(task_,
                             task_settings{.name = task_name_, .kind = task_kind::cyclic, .interval = cycle_time_});
      task_driver::begin(task_, now_);
      {
        // current_task() in the body is the driver's task; a fault names the task and program of
        // the context the cycles run in, as before.
        iecoop::fault_context context = *iecoop::detail::current_fault_context;
        context.cycle_task = &task_;
        const iecoop::detail::fault_context_scope current(context);
        this->forces_.apply_at_start();
        detail::call_guarded(body_);  // a call through an unassigned interface ends it (faults.hpp)
        this->forces_.apply_at_end();
      }
      task_driver::end(task_, now_);
      now_ = now_ + cycle_time_;
      ++cycle_;
      this->stepped();
    }
  }

  /// The body's task, as current_task() shows it in the body: its cycles, their start, the
  /// first-cycle flag, statistics().
  [[nodiscard]] const task_info& task() const noexcept { return task_; }
  /// Names the body's task (current_task().name(), TwinCAT's TaskName) from the next cycle on;
  /// `name` must outlive the driver (a string literal).
  void set_task_name(const char* name) noexcept { task_name_ = name; }

 private:
  Body body_;
  LTIME cycle_time_;
  LTIME now_;
  std::uint64_t cycle_ = 0;
  const char* task_name_ = "testing::cycles";
  task_info task_;
};

template <class B>
cycles(B&&) -> cycles<B>;
template <class B>
cycles(B&&, iecoop::detail::duration_argument) -> cycles<B>;
template <class B>
cycles(B&&, iecoop::detail::duration_argument, iecoop::detail::duration_argument) -> cycles<B>;

}  // namespace iecoop::testing

#include <iecoop/detail/pop_macros.hpp>
