// SPDX-License-Identifier: MIT
// iecoop/types/time.hpp — IEC durations TIME and LTIME in their CODESYS representation, with
// std::chrono interoperability.
//
// TIME is an unsigned 32-bit count of milliseconds (T#0ms .. T#49d17h2m47s295ms) and LTIME
// an unsigned 64-bit count of nanoseconds (LTIME#0ns .. LTIME#213503d23h34m33s709ms551us615ns),
// exactly as CODESYS and TwinCAT store them (IEC itself calls durations signed; CODESYS
// treats TIME as UDINT and LTIME as ULINT). Arithmetic wraps modulo 2^32 ms / 2^64 ns, as
// it does on those PLCs: T#0ms - T#1ms is T#49d17h2m47s295ms.
#pragma once

#include <compare>
#include <concepts>
#include <cstdint>
#include <limits>
#include <ratio>
#include <type_traits>
#include <utility>

#include <iecoop/config.hpp>
#include <iecoop/detail/chrono.hpp>  // std::chrono's durations and clocks
#include <iecoop/detail/constant_division.hpp>
#include <iecoop/detail/diagnostics.hpp>
#include <iecoop/detail/iec_value.hpp>
#include <iecoop/detail/scalar_access.hpp>
#include <iecoop/fault.hpp>
#include <iecoop/types/detail/float_to_int.hpp>
#include <iecoop/types/elementary.hpp>

#include <iecoop/detail/push_macros.hpp>

namespace iecoop {

namespace detail {

/// The value of an IEC or C++ number usable as a factor of a duration (also an intermediate
/// result: `tCycle * (n + 1)`).
template <class T>
concept duration_factor = cpp_integer<T> || std::floating_point<T> || AnyNum<T> || Intermediate<T>;

}  // namespace detail

/**
 * An IEC duration: `Rep` ticks of `Period` seconds, unsigned, wrapping. Use the aliases
 * TIME (32-bit milliseconds) and LTIME (64-bit nanoseconds).
 *
 *     using namespace std::chrono_literals;
 *     TIME t = 1500ms;                      // from std::chrono, wherever no precision is lost
 *     TIME pt = "T#1s500ms"_iec;            // IEC literal, checked at compile time
 *     TIME p = 300;                         // an integer constant means milliseconds (CODESYS)
 *     std::chrono::milliseconds c = t;      // back to std::chrono
 *     t.count();                            // 1500
 */
template <class Rep, class Period>
class basic_time {
  static_assert(std::is_unsigned_v<Rep>, "iecoop: TIME and LTIME are unsigned, as in CODESYS");

 public:
  using rep = Rep;
  using period = Period;
  /// The std::chrono duration with the same representation.
  using chrono_type = std::chrono::duration<Rep, Period>;

  constexpr basic_time() noexcept = default;

  /// An integer constant counts ticks (TIME: milliseconds), as `PT := 300` does in CODESYS.
  /// Checked at compile time: it must be a non-negative constant that fits.
  template <detail::cpp_integer T>
  consteval basic_time(T ticks) : value_(static_cast<Rep>(ticks)) {  // implicit on purpose
    if (!std::in_range<Rep>(ticks)) {
      // The compiler shows the call's line, which must hold the whole message.
      // clang-format off
      detail::compile_error("iecoop: duration constant out of range (TIME and LTIME are unsigned); use a T# literal or a std::chrono duration");
      // clang-format on
    }
  }

  /// From std::chrono durations that are whole multiples of the tick (ms, s, min, h for
  /// TIME; anything from ns for LTIME). The value wraps modulo 2^bits like every TIME
  /// operation. Convert finer durations with std::chrono::duration_cast first.
  template <std::integral R, class P>
    requires(std::ratio_divide<P, Period>::den == 1)
  constexpr basic_time(std::chrono::duration<R, P> d) noexcept  // implicit on purpose
      : value_(static_cast<Rep>(static_cast<std::uint64_t>(d.count()) *
                                static_cast<std::uint64_t>(std::ratio_divide<P, Period>::num))) {}

  /// From another IEC duration: TIME -> LTIME is implicit (exact); LTIME -> TIME explicit
  /// (truncates to whole milliseconds and wraps, like LTIME_TO_TIME).
  template <class R, class P>
    requires(!std::is_same_v<basic_time<R, P>, basic_time>)
  constexpr explicit(std::ratio_divide<P, Period>::den != 1 || sizeof(R) > sizeof(Rep))
      basic_time(basic_time<R, P> other) noexcept
      : value_(static_cast<Rep>(scale<P>(static_cast<std::uint64_t>(other.count())))) {}

  /// To std::chrono durations that lose no precision (the same rule std::chrono applies;
  /// as there, the range is yours to watch).
  template <class R, class P>
    requires(std::is_floating_point_v<R> || (std::integral<R> && std::ratio_divide<Period, P>::den == 1))
  constexpr operator std::chrono::duration<R, P>() const noexcept {  // implicit on purpose
    return std::chrono::duration_cast<std::chrono::duration<R, P>>(chrono_type(value_));
  }

  /// The number of ticks: milliseconds for TIME, nanoseconds for LTIME.
  [[nodiscard]] constexpr Rep count() const noexcept { return value_; }
  /// The same duration as a std::chrono duration.
  [[nodiscard]] constexpr chrono_type chrono() const noexcept { return chrono_type(value_); }

  static constexpr basic_time zero() noexcept { return basic_time(); }
  static constexpr basic_time max() noexcept { return from_ticks(std::numeric_limits<Rep>::max()); }
  /// A duration of `ticks` ticks, wrapping (for a run-time tick count).
  static constexpr basic_time from_ticks(Rep ticks) noexcept {
    basic_time t;
    t.value_ = ticks;
    return t;
  }

  friend constexpr basic_time operator+(basic_time a, basic_time b) noexcept {
    return from_ticks(static_cast<Rep>(a.wide() + b.wide()));
  }
  friend constexpr basic_time operator-(basic_time a, basic_time b) noexcept {
    return from_ticks(static_cast<Rep>(a.wide() - b.wide()));
  }
  constexpr basic_time& operator+=(basic_time b) noexcept { return *this = *this + b; }
  constexpr basic_time& operator-=(basic_time b) noexcept { return *this = *this - b; }

  /// ST's MUL(TIME, ANY_NUM): integer factors wrap, REAL factors round to the tick.
  template <detail::duration_factor N>
  friend constexpr basic_time operator*(basic_time a, N factor) noexcept {
    if constexpr (is_floating<N>()) {
      return from_ticks(
          static_cast<Rep>(detail::round_to_int64(static_cast<long double>(a.value_) * as_long_double(factor))));
    } else {
      return from_ticks(static_cast<Rep>(a.wide() * static_cast<wide_t>(as_int64(factor))));
    }
  }
  template <detail::duration_factor N>
  friend constexpr basic_time operator*(N factor, basic_time a) noexcept {
    return a * factor;
  }
  /// ST's DIV(TIME, ANY_NUM): truncates toward zero (REAL divisors round); by zero it
  /// reports fault_kind::division_by_zero and yields 0.
  template <detail::duration_factor N>
  friend constexpr basic_time operator/(basic_time a, N divisor) {
    if constexpr (is_floating<N>()) {
      const long double d = as_long_double(divisor);
      if (d == 0) return divide_by_zero();
      return from_ticks(static_cast<Rep>(detail::round_to_int64(static_cast<long double>(a.value_) / d)));
    } else {
      const std::int64_t d = as_int64(divisor);
      if (d == 0) return divide_by_zero();
      if (d > 0) return from_ticks(static_cast<Rep>(a.value_ / static_cast<std::uint64_t>(d)));
      // A negative divisor: the quotient is negative and wraps like every TIME result.
      return from_ticks(static_cast<Rep>(wide_t{0} - a.value_ / (wide_t{0} - static_cast<std::uint64_t>(d))));
    }
  }
  template <detail::duration_factor N>
  constexpr basic_time& operator*=(N factor) noexcept {
    return *this = *this * factor;
  }
  template <detail::duration_factor N>
  constexpr basic_time& operator/=(N divisor) {
    return *this = *this / divisor;
  }

  // Comparisons yield BOOL, as in ST.
  friend constexpr BOOL operator==(basic_time a, basic_time b) noexcept { return BOOL(a.value_ == b.value_); }
  friend constexpr BOOL operator!=(basic_time a, basic_time b) noexcept { return BOOL(a.value_ != b.value_); }
  friend constexpr BOOL operator<(basic_time a, basic_time b) noexcept { return BOOL(a.value_ < b.value_); }
  friend constexpr BOOL operator<=(basic_time a, basic_time b) noexcept { return BOOL(a.value_ <= b.value_); }
  friend constexpr BOOL operator>(basic_time a, basic_time b) noexcept { return BOOL(a.value_ > b.value_); }
  friend constexpr BOOL operator>=(basic_time a, basic_time b) noexcept { return BOOL(a.value_ >= b.value_); }
  friend constexpr std::strong_ordering operator<=>(basic_time a, basic_time b) noexcept {
    return a.value_ <=> b.value_;
  }

 private:
  using wide_t = std::uint64_t;  // arithmetic is done here and truncated: modular, no UB

  constexpr wide_t wide() const noexcept { return value_; }

  template <class P>
  static constexpr std::uint64_t scale(std::uint64_t ticks) noexcept {
    using ratio = std::ratio_divide<P, Period>;
    // To a coarser unit (LTIME to TIME: the cycle clock, every task cycle) without a 64-bit
    // division on a 32-bit core (detail/constant_division.hpp).
    return detail::divide_by<static_cast<std::uint64_t>(ratio::den)>(ticks * static_cast<std::uint64_t>(ratio::num));
  }

  template <class N>
  static constexpr bool is_floating() noexcept {
    return std::floating_point<N> || AnyReal<N>;
  }
  template <class N>
  static constexpr long double as_long_double(N n) noexcept {
    if constexpr (AnyReal<N>) {
      return static_cast<long double>(n.value());
    } else {
      return static_cast<long double>(n);
    }
  }
  template <class N>
  static constexpr std::int64_t as_int64(N n) noexcept {
    if constexpr (AnyInt<N> || Intermediate<N>) {
      return static_cast<std::int64_t>(n.value());  // ULINT factors above 2^63 wrap, harmlessly
    } else {
      return static_cast<std::int64_t>(n);
    }
  }

  static basic_time divide_by_zero() {
    fault(fault_kind::division_by_zero, "duration divided by zero; the result is 0");
    return basic_time();
  }

  friend struct detail::scalar_access;
  Rep value_ = 0;
};

template <class Rep, class Period>
struct detail::is_scalar_wrapper<basic_time<Rep, Period>> : std::true_type {};
template <class Rep, class Period>
struct detail::is_iec_value<basic_time<Rep, Period>> : std::true_type {};

/// IEC TIME as CODESYS stores it: unsigned 32-bit milliseconds.
using TIME = basic_time<std::uint32_t, std::milli>;
/// IEC LTIME as CODESYS stores it: unsigned 64-bit nanoseconds.
using LTIME = basic_time<std::uint64_t, std::nano>;

template <>
struct detail::iec_name<TIME> {
  static constexpr std::string_view value = "TIME";
};
template <>
struct detail::iec_name<LTIME> {
  static constexpr std::string_view value = "LTIME";
};

namespace detail {
template <class T>
struct is_time : std::false_type {};
template <class R, class P>
struct is_time<basic_time<R, P>> : std::true_type {};
}  // namespace detail

/// TIME or LTIME (IEC ANY_DURATION).
template <class T>
concept AnyDuration = detail::is_time<T>::value;

}  // namespace iecoop

#include <iecoop/detail/pop_macros.hpp>
