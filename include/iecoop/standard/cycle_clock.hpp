// SPDX-License-Identifier: MIT
// iecoop/standard/cycle_clock.hpp — the time stamp of the task cycle that is running: the one clock
// every timer (TON, TOF, TP, ...) reads.
//
// A PLC samples the time once when a task cycle starts; every timer called during that cycle
// sees the same time, however long the cycle takes, and time does not pass between two calls
// of the same timer in one cycle. iecoop never reads a wall clock inside a block: whoever
// runs the cycle — the scheduler, a test, a firmware's SysTick handler — sets the time stamp
// before the cycle, and can set it to anything, so an hour of machine time is one call.
//
//     cycle_clock::set(T#0ms);          tmr("IN"_ = TRUE, "PT"_ = T#5s);   // ST: T#5s
//     cycle_clock::advance(T#5s);       tmr();   // tmr.Q is TRUE
//
// The time stamp counts from an arbitrary origin (the runtime's start) and only ever goes
// forward while timers run; timers measure differences of it, modulo the width of their
// TIME type, so the 49.7-day wrap of TIME's 32-bit milliseconds is harmless.
#pragma once

#include <type_traits>

#include <iecoop/config.hpp>
#include <iecoop/standard/detail/duration_argument.hpp>
#include <iecoop/types/time.hpp>

#include <iecoop/detail/push_macros.hpp>

namespace iecoop {

/**
 * The current task cycle's time stamp (static: there is one per program image, as on a PLC).
 * Set it once per cycle before the cycle's programs run; read it with now() (LTIME) or
 * now_as<TIME>(). Setting it is not synchronised: set and read it from the thread that runs
 * the cycles. A scheduler that interrupts one task's cycle with another's uses `scope` to give
 * the interrupted cycle its own time stamp back.
 */
class cycle_clock {
  // Both widths, converted once per cycle, so that a timer reads its own width without a
  // division on every call.
  struct stamp {
    LTIME ltime;
    TIME time;
  };

 public:
  /// The time stamp of the running cycle, in LTIME's nanoseconds.
  [[nodiscard]] static LTIME now() noexcept { return stamp_.ltime; }

  /// The time stamp as TIME (milliseconds, what TON and friends read) or LTIME.
  template <class Time>
  [[nodiscard]] static Time now_as() noexcept {
    static_assert(std::is_same_v<Time, TIME> || std::is_same_v<Time, LTIME>,
                  "iecoop: the cycle clock is read as TIME or LTIME; use now_as<TIME>() or now_as<LTIME>()");
    if constexpr (std::is_same_v<Time, TIME>) {
      return stamp_.time;
    } else {
      return stamp_.ltime;
    }
  }

  /// Sets the time stamp of the cycle about to run.
  static void set(LTIME now) noexcept { stamp_ = stamp{now, TIME(now)}; }
  /// Moves the time stamp forward by `elapsed` (wrapping like every LTIME operation): a TIME,
  /// an LTIME or a std::chrono duration; `advance(2000)` does not compile (2000 what?).
  static void advance(detail::duration_argument elapsed) noexcept { set(now() + elapsed.get()); }

  /// Sets the time stamp for the lifetime of the scope and then restores the one before: a
  /// task cycle that interrupts another one leaves the interrupted cycle's time untouched.
  class scope {
   public:
    explicit scope(LTIME now) noexcept : saved_(stamp_) { set(now); }
    ~scope() { stamp_ = saved_; }
    scope(const scope&) = delete;
    scope& operator=(const scope&) = delete;

   private:
    stamp saved_;
  };

 private:
  static inline stamp stamp_{};
};

/// ST's `TIME()` and `LTIME()`, the controller's time since it started: `TIME(system_time)`
/// and `LTIME(system_time)` (`TIME()` in C++ is a TIME of 0 ms). iecoop's controller time is the
/// cycle clock: the running task cycle's start, the same all through the cycle (CODESYS reads
/// its running clock at each call).
struct system_time_t {
  template <class Rep, class Period>
  constexpr operator basic_time<Rep, Period>() const noexcept {  // implicit: TIME(system_time)
    return cycle_clock::now_as<basic_time<Rep, Period>>();
  }
};
inline constexpr system_time_t system_time{};

}  // namespace iecoop

#include <iecoop/detail/pop_macros.hpp>
