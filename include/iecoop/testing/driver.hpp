// SPDX-License-Identifier: MIT
// iecoop/testing/driver.hpp — what the kit's two drivers (testing::cycles over one block or
// program, testing::plc over an application) have in common: stepping simulated time, waiting
// for a condition with a timeout, pulsing an input, forcing, and the timing diagrams.
//
//     step();                                   // one cycle (an application: one base cycle)
//     step(10);                                 // ten
//     advance("T#5s"_iec);                      // the cycles of the next five seconds
//     REQUIRE(run_until([&] { return fb.Q; }, "T#3s"_iec));   // at most T#3s
//     REQUIRE(run_until(fb.Q, "T#3s"_iec));     // a BOOL variable, output or located input
//     pulse(io.ixStart);                        // TRUE for one cycle, then as before
//     pulse(io.ixStart, 5);                     // for five
//
// run_until's result tells, when the condition was not met, the simulated time spent and the
// cycle reached; doctest's message adds the condition's text. Time is simulated throughout:
// an hour of cycles takes what the programs take to run, nothing more.
// IWYU pragma: private, include <iecoop/testing.hpp>
#pragma once

#include <concepts>
#include <cstdint>
#include <ostream>
#include <type_traits>

#include <iecoop/ostream.hpp>
#include <iecoop/standard/detail/duration_argument.hpp>
#include <iecoop/testing/faults.hpp>
#include <iecoop/testing/forcing.hpp>
#include <iecoop/types/elementary.hpp>
#include <iecoop/types/time.hpp>

#include <iecoop/detail/push_macros.hpp>

namespace iecoop::testing {

/// What run_until() found: TRUE if the condition was met in time. Printed in a failed check:
/// "met after T#2s1ms (2001 cycles)" or "not met within T#3s: 3000 cycles run, cycle 3500,
/// cycle clock T#3s500ms".
struct wait_result {
  bool met = false;
  bool stopped_by_fault = false;  ///< the test case had a fault: the driver ran no more cycles
  LTIME timeout{};
  LTIME waited{};            ///< simulated time spent waiting
  std::uint64_t cycles = 0;  ///< cycles run while waiting
  std::uint64_t cycle = 0;   ///< the driver's cycle count at the end
  LTIME now{};               ///< the driver's time at the end

  explicit operator bool() const noexcept { return met; }

  friend std::ostream& operator<<(std::ostream& os, const wait_result& r) {
    if (r.met) return os << "met after " << TIME(r.waited) << " (" << r.cycles << " cycles)";
    os << (r.stopped_by_fault ? "not met: a fault stopped the cycles after " : "not met within ")
       << (r.stopped_by_fault ? TIME(r.waited) : TIME(r.timeout)) << ": " << r.cycles << " cycles run, cycle "
       << r.cycle << ", time " << TIME(r.now);
    return os;
  }
};

namespace detail {
/// A condition: something callable that returns a BOOL or bool, or a BOOL variable (any
/// wrapper of one) read after each cycle.
template <class C>
bool holds(C& condition) {
  if constexpr (std::invocable<C&>) {
    return static_cast<bool>(condition());
  } else {
    static_assert(std::is_constructible_v<BOOL, C&>,
                  "iecoop: run_until waits for a condition: a BOOL variable or a callable that returns BOOL or bool; "
                  "write a comparison as a lambda, e.g. run_until([&] { return fb.iCount == 3; }, T)");
    if constexpr (std::is_constructible_v<BOOL, C&>) return static_cast<bool>(BOOL(condition));
    return false;
  }
}
}  // namespace detail

/**
 * The common part of the drivers. `Derived` provides run_cycles(n) (n of its steps),
 * step_time() (the simulated time of one step), now() and cycle() (steps run).
 */
template <class Derived>
class driver {
 public:
  /// Runs `n` cycles (an application: `n` base cycles, each task as often as it is due).
  void step(std::uint64_t n = 1, call_site where = call_site::current()) {
    const detail::driving_scope driving(where);
    run(n);
  }

  /// Runs the cycles due in the next `duration` of simulated time (rounded up to whole steps).
  /// A duration is TIME, LTIME or std::chrono: `advance(3000)` does not compile (3000 what?).
  void advance(iecoop::detail::duration_argument duration, call_site where = call_site::current()) {
    const detail::driving_scope driving(where);
    run(steps_in(duration));
  }

  /// Runs cycles until `condition` holds (checked before the first and after each cycle), for
  /// at most `timeout` of simulated time. Use it in REQUIRE or CHECK: [[nodiscard]].
  template <class C>
  [[nodiscard]] wait_result run_until(C&& condition, iecoop::detail::duration_argument timeout,
                                      call_site where = call_site::current()) {
    const detail::driving_scope driving(where);
    wait_result r;
    r.timeout = timeout;
    const LTIME start = self().now();
    const std::uint64_t first = self().cycle();
    const std::uint64_t limit = steps_in(timeout);
    r.met = detail::holds(condition);
    for (std::uint64_t i = 0; !r.met && i < limit; ++i) {
      if (faulted()) {
        r.stopped_by_fault = true;
        break;
      }
      self().run_cycles(1);
      r.met = detail::holds(condition);
    }
    r.cycle = self().cycle();
    r.cycles = r.cycle - first;
    r.now = self().now();
    r.waited = r.now - start;
    return r;
  }

  /// Sets the BOOL `input` to `value` (TRUE) for `cycles` cycles (forced: the field and the
  /// program cannot change it meanwhile), then gives it back the value it had before.
  template <class V>
  void pulse(V& input, std::uint64_t cycles = 1, BOOL value = TRUE, call_site where = call_site::current()) {
    const detail::driving_scope driving(where);
    // A forced input gets its forced value back (which the variable does not hold yet if no
    // cycle ran since it was forced), at once, as an input not forced gets its value.
    const auto forced_before = forces_.forced_value(input);
    const BOOL before = forced_before ? BOOL(*forced_before) : static_cast<BOOL>(input);
    forces_.force(input, value);
    run(cycles);
    if (forced_before) {
      forces_.force(input, before);
    } else {
      forces_.release(input);
    }
    detail::write_variable(input, before);
  }

  // --- Forcing (forcing.hpp) -----------------------------------------------------------

  /// Forces `variable` to `value` from the next cycle on, at each cycle's start and end.
  template <class V, class T>
  void force(V& variable, const T& value) {
    forces_.force(variable, value);
  }
  /// Writes `value` to `variable` once, at the next cycle's start.
  template <class V, class T>
  void write(V& variable, const T& value) {
    forces_.write(variable, value);
  }
  template <class V>
  void release(const V& variable) noexcept {
    forces_.release(variable);
  }
  /// Releases `variable` and gives it back its value from before the force.
  template <class V>
  void release_and_restore(V& variable) {
    forces_.release_and_restore(variable);
  }
  void release_all() noexcept { forces_.release_all(); }
  template <class V>
  [[nodiscard]] bool forced(const V& variable) const noexcept {
    return forces_.forced(variable);
  }
  [[nodiscard]] std::size_t forced_count() const noexcept { return forces_.forced_count(); }

  /// Called after each step (the timing diagrams' recorder); nullptr: none.
  void on_step(void (*after_step)(void*), void* context) noexcept {
    after_step_ = after_step;
    after_step_context_ = context;
  }

 protected:
  driver() = default;
  ~driver() = default;
  driver(const driver&) = delete;
  driver& operator=(const driver&) = delete;

  force_table forces_;

  void stepped() {
    if (after_step_ != nullptr) after_step_(after_step_context_);
  }

 private:
  Derived& self() noexcept { return static_cast<Derived&>(*this); }

  [[nodiscard]] std::uint64_t steps_in(LTIME duration) const noexcept {
    const auto step = static_cast<const Derived&>(*this).step_time().count();
    const auto d = duration.count();
    return d <= 0 || step <= 0 ? 0 : static_cast<std::uint64_t>((d + step - 1) / step);
  }

  void run(std::uint64_t n) {
    for (std::uint64_t i = 0; i < n && !faulted(); ++i) self().run_cycles(1);
  }

  void (*after_step_)(void*) = nullptr;
  void* after_step_context_ = nullptr;
};

}  // namespace iecoop::testing

#include <iecoop/detail/pop_macros.hpp>
