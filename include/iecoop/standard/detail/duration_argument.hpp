// SPDX-License-Identifier: MIT
// iecoop/standard/detail/duration_argument.hpp — the duration a function that runs simulated time takes
// (the test kit's advance(), run_until()'s timeout, testing::cycles' cycle time; an
// application's run_for(); cycle_clock::advance()): a TIME, an LTIME, a variable of one or a
// std::chrono duration, never a bare number. ST has no step from a number to a TIME, and
// `advance(3000)` would otherwise be LTIME's 3000 ns, not the 3 s its writer meant.
// IWYU pragma: private, include <iecoop/iecoop.hpp>
#pragma once

#include <type_traits>

#include <iecoop/detail/chrono.hpp>  // std::chrono's durations and clocks
#include <iecoop/detail/meta.hpp>
#include <iecoop/types/detail/value_operators.hpp>
#include <iecoop/types/time.hpp>

#include <iecoop/detail/push_macros.hpp>

namespace iecoop::detail {

template <class D>
struct is_chrono_duration : std::false_type {};
template <class R, class P>
struct is_chrono_duration<std::chrono::duration<R, P>> : std::true_type {};

/// What a duration argument accepts: TIME or LTIME (or a variable wrapper of one), or a
/// std::chrono duration that LTIME holds exactly (whole nanoseconds).
template <class D>
concept duration_value = AnyDuration<unwrapped_t<D>> || (is_chrono_duration<std::remove_cvref_t<D>>::value &&
                                                         std::is_convertible_v<std::remove_cvref_t<D>, LTIME>);

/**
 * A parameter that takes a duration as the caller writes it — `"T#3s"_iec`, `tCycle`,
 * `fb.PT`, `3s` — and refuses anything else at compile time, a number in particular (which
 * unit would it be?). It reads as the LTIME it holds.
 */
class duration_argument {
 public:
  template <class D>
  constexpr duration_argument(const D& duration) noexcept  // implicit: the caller writes the duration itself
      : value_(ltime_of(duration)) {
    // Here, not in ltime_of: one instantiation note fewer before the caller's line.
    static_assert(duration_value<D>,
                  "iecoop: a duration is a TIME, an LTIME or a std::chrono duration of whole nanoseconds, not a bare "
                  "number (which unit?); write it with its unit, e.g. \"T#3s\"_iec or 3s (std::chrono_literals)");
  }

  constexpr operator LTIME() const noexcept { return value_; }  // implicit: reads as the duration it holds
  [[nodiscard]] constexpr LTIME get() const noexcept { return value_; }

 private:
  template <class D>
  static constexpr LTIME ltime_of(const D& duration) noexcept {
    if constexpr (AnyDuration<unwrapped_t<D>>) {
      return LTIME(value_of(duration));
    } else if constexpr (duration_value<D>) {
      return LTIME(duration);
    } else {
      return LTIME{};  // refused by the constructor
    }
  }

  LTIME value_;
};

}  // namespace iecoop::detail

#include <iecoop/detail/pop_macros.hpp>
