// SPDX-License-Identifier: MIT
// iecoop/types/date_time.hpp — the IEC points in time DATE, TIME_OF_DAY (TOD) and DATE_AND_TIME
// (DT) and their long forms LDATE, LTIME_OF_DAY (LTOD) and LDATE_AND_TIME (LDT), in their
// CODESYS representation.
//
// CODESYS stores them as unsigned counts, and so does iecoop (the values CODESYS shows):
//
//   DATE   32-bit seconds since 1970-01-01 (only the day is shown)  D#1970-01-01 .. D#2106-02-07
//   DT     32-bit seconds since 1970-01-01        DT#1970-01-01-00:00:00 .. DT#2106-02-07-06:28:15
//   TOD    32-bit milliseconds since midnight                TOD#00:00:00 .. TOD#23:59:59.999
//   LDATE  64-bit nanoseconds since 1970-01-01                LDATE#1970-01-01 .. LDATE#2554-07-21
//   LDT    64-bit nanoseconds since 1970-01-01  LDT#1970-01-01-00:00:00 .. LDT#2554-07-21-23:34:33.709551615
//   LTOD   64-bit nanoseconds since midnight           LTOD#00:00:00 .. LTOD#23:59:59.999999999
//
// The operators are the ones CODESYS's ADD and SUB take for points in time: TOD + TIME = TOD,
// DT + TIME = DT, TOD - TIME = TOD, DT - TIME = DT, TOD - TOD = TIME, DT - DT = TIME,
// DATE - DATE = TIME (and the L forms; a 32-bit point meeting an LTIME gives the L point).
// Arithmetic wraps modulo 2^32 / 2^64 as on the PLC's DWORD and LWORD: a TOD does not wrap at
// midnight (TOD#23:00:00 + T#2h holds 25 hours), DT#1970-01-01-00:00:00 - T#1s is
// DT#2106-02-07-06:28:15, and a difference too large for TIME (more than 49 days) wraps.
// Anything else (DATE + DATE, DATE + TIME, a point times a number) does not compile, with a
// message. A point never converts implicitly to a number: use DATE_TO_UDINT(d) and friends.
#pragma once

#include <compare>
#include <cstdint>
#include <limits>
#include <ratio>
#include <string_view>
#include <type_traits>

#include <iecoop/config.hpp>
#include <iecoop/detail/chrono.hpp>  // std::chrono's durations and clocks
#include <iecoop/detail/diagnostics.hpp>
#include <iecoop/detail/iec_value.hpp>
#include <iecoop/detail/scalar_access.hpp>
#include <iecoop/types/elementary.hpp>
#include <iecoop/types/time.hpp>

#include <iecoop/detail/push_macros.hpp>

namespace iecoop {

/// What a point in time counts from: DATE and DATE_AND_TIME from 1970-01-01 (a DATE shows only
/// the day), TIME_OF_DAY from midnight.
enum class time_point_kind : unsigned char {
  date,           ///< DATE, LDATE
  time_of_day,    ///< TIME_OF_DAY (TOD), LTIME_OF_DAY (LTOD)
  date_and_time,  ///< DATE_AND_TIME (DT), LDATE_AND_TIME (LDT)
};

template <class Rep, class Period, time_point_kind Kind>
class basic_time_point;

namespace detail {
template <class T>
struct is_time_point : std::false_type {};
template <class Rep, class Period, time_point_kind Kind>
struct is_time_point<basic_time_point<Rep, Period, Kind>> : std::true_type {};

inline constexpr std::uint64_t seconds_per_day = 86'400;

/// The number of days from 1970-01-01 to the Gregorian date y-m-d (y >= 1970, m 1..12,
/// d 1..31): whole 400-year cycles from 0000-03-01, then years, then months from March (which
/// puts the leap day at the end of the year).
constexpr std::uint64_t days_from_civil(std::uint64_t y, std::uint64_t m, std::uint64_t d) noexcept {
  if (m <= 2) --y;  // January and February belong to the year before, counted from March
  const std::uint64_t cycle = y / 400;
  const std::uint64_t year_of_cycle = y % 400;
  const std::uint64_t month_from_march = m > 2 ? m - 3 : m + 9;
  const std::uint64_t day_of_year = (153 * month_from_march + 2) / 5 + d - 1;
  const std::uint64_t day_of_cycle = year_of_cycle * 365 + year_of_cycle / 4 - year_of_cycle / 100 + day_of_year;
  constexpr std::uint64_t days_0000_03_01_to_1970_01_01 = 719'468;
  return cycle * 146'097 + day_of_cycle - days_0000_03_01_to_1970_01_01;
}

/// A calendar date.
struct civil_date {
  std::uint64_t year;
  std::uint64_t month;
  std::uint64_t day;
};

/// The Gregorian date `days` days after 1970-01-01 (the inverse of days_from_civil).
constexpr civil_date civil_from_days(std::uint64_t days) noexcept {
  const std::uint64_t z = days + 719'468;
  const std::uint64_t cycle = z / 146'097;
  const std::uint64_t day_of_cycle = z % 146'097;
  const std::uint64_t year_of_cycle =
      (day_of_cycle - day_of_cycle / 1460 + day_of_cycle / 36'524 - day_of_cycle / 146'096) / 365;
  const std::uint64_t day_of_year = day_of_cycle - (365 * year_of_cycle + year_of_cycle / 4 - year_of_cycle / 100);
  const std::uint64_t month_from_march = (5 * day_of_year + 2) / 153;
  const std::uint64_t day = day_of_year - (153 * month_from_march + 2) / 5 + 1;
  const std::uint64_t month = month_from_march < 10 ? month_from_march + 3 : month_from_march - 9;
  const std::uint64_t year = year_of_cycle + cycle * 400 + (month <= 2 ? 1 : 0);
  return {year, month, day};
}

constexpr bool is_leap_year(std::uint64_t y) noexcept { return y % 4 == 0 && (y % 100 != 0 || y % 400 == 0); }

/// The number of days of month m (1..12) in year y; 0 for a month that does not exist.
constexpr std::uint64_t days_in_month(std::uint64_t y, std::uint64_t m) noexcept {
  constexpr std::uint64_t days[] = {31, 28, 31, 30, 31, 30, 31, 31, 30, 31, 30, 31};
  if (m < 1 || m > 12) return 0;
  return m == 2 && is_leap_year(y) ? 29 : days[m - 1];
}

/// The point type of the same kind with 64-bit nanoseconds (LDATE for DATE).
template <class P>
using long_point_t = basic_time_point<std::uint64_t, std::nano, P::kind>;

/// The ticks of a point of period P as nanoseconds, modulo 2^64.
template <class P>
constexpr std::uint64_t ticks_to_ns(std::uint64_t ticks) noexcept {
  return ticks * static_cast<std::uint64_t>(std::ratio_divide<P, std::nano>::num);
}
}  // namespace detail

/**
 * An IEC point in time: `Rep` ticks of `Period` seconds since the start of `Kind` (1970-01-01,
 * or midnight). Use the aliases DATE, TOD (TIME_OF_DAY), DT (DATE_AND_TIME), LDATE, LTOD
 * (LTIME_OF_DAY) and LDT (LDATE_AND_TIME).
 *
 *     DT dtStart = "DT#2026-11-23-12:30:00"_iec;   // checked at compile time
 *     DT dtEnd = dtStart + "T#90m"_iec;            // DT + TIME = DT
 *     TIME tTaken = dtEnd - dtStart;               // DT - DT = TIME
 *     dtStart.count();                             // 1795437000: seconds since 1970
 *
 * Zero by default (D#1970-01-01, TOD#00:00:00), trivially copyable, exactly the size CODESYS
 * gives it. The 32-bit types widen implicitly to their L forms, as IEC widens DATE to LDATE;
 * the other way is explicit (LDATE_TO_DATE). Comparisons yield BOOL.
 */
template <class Rep, class Period, time_point_kind Kind>
class basic_time_point {
  static_assert(std::is_unsigned_v<Rep>, "iecoop: DATE, TOD and DT are unsigned, as in CODESYS");

 public:
  using rep = Rep;
  using period = Period;
  static constexpr time_point_kind kind = Kind;
  /// The duration of the same width: TIME for the 32-bit types, LTIME for the L forms.
  using duration = std::conditional_t<(sizeof(Rep) > 4), LTIME, TIME>;

  constexpr basic_time_point() noexcept = default;

  /// From the 32-bit form of the same kind: DATE -> LDATE, TOD -> LTOD, DT -> LDT are exact
  /// and implicit (IEC's implicit widening); the other way truncates to the tick and wraps,
  /// and is explicit (LDATE_TO_DATE).
  template <class R, class P>
    requires(!std::is_same_v<R, Rep>)
  constexpr explicit(sizeof(R) > sizeof(Rep)) basic_time_point(basic_time_point<R, P, Kind> other) noexcept
      : value_(static_cast<Rep>(static_cast<std::uint64_t>(other.count()) *
                                static_cast<std::uint64_t>(std::ratio_divide<P, Period>::num) /
                                static_cast<std::uint64_t>(std::ratio_divide<P, Period>::den))) {}

  /// Assigning a value of another IEC type (`d = dt;`, `d = udiSeconds;`): rejected, naming
  /// the conversion to write (DT_TO_DATE(dt), UDINT_TO_DATE(udiSeconds)).
  template <class V>
    requires detail::rejected_conversion<V, basic_time_point>
  constexpr void operator=(const V&) noexcept {
    detail::no_implicit_conversion<detail::spelled_iec_name_t<detail::nominal_t<V>>,
                                   detail::spelled_iec_name_t<basic_time_point>>();
  }

  /// The number of ticks since 1970-01-01 (or midnight): seconds for DATE and DT,
  /// milliseconds for TOD, nanoseconds for the L forms.
  [[nodiscard]] constexpr Rep count() const noexcept { return value_; }
  /// The time since 1970-01-01 (or midnight) as a std::chrono duration.
  [[nodiscard]] constexpr std::chrono::duration<Rep, Period> time_since_epoch() const noexcept {
    return std::chrono::duration<Rep, Period>(value_);
  }

  /// The point `ticks` ticks after 1970-01-01 (or midnight), wrapping.
  static constexpr basic_time_point from_ticks(Rep ticks) noexcept {
    basic_time_point p;
    p.value_ = ticks;
    return p;
  }
  static constexpr basic_time_point min() noexcept { return basic_time_point(); }
  static constexpr basic_time_point max() noexcept { return from_ticks(std::numeric_limits<Rep>::max()); }

  // Comparisons yield BOOL, as in ST. (A DATE meets an LDATE as an LDATE: the LDATE's
  // operators take the widened DATE.)
  friend constexpr BOOL operator==(basic_time_point a, basic_time_point b) noexcept {
    return BOOL(a.value_ == b.value_);
  }
  friend constexpr BOOL operator!=(basic_time_point a, basic_time_point b) noexcept {
    return BOOL(a.value_ != b.value_);
  }
  friend constexpr BOOL operator<(basic_time_point a, basic_time_point b) noexcept { return BOOL(a.value_ < b.value_); }
  friend constexpr BOOL operator<=(basic_time_point a, basic_time_point b) noexcept {
    return BOOL(a.value_ <= b.value_);
  }
  friend constexpr BOOL operator>(basic_time_point a, basic_time_point b) noexcept { return BOOL(a.value_ > b.value_); }
  friend constexpr BOOL operator>=(basic_time_point a, basic_time_point b) noexcept {
    return BOOL(a.value_ >= b.value_);
  }
  friend constexpr std::strong_ordering operator<=>(basic_time_point a, basic_time_point b) noexcept {
    return a.value_ <=> b.value_;
  }

  /// DATE - DATE, TOD - TOD, DT - DT = TIME; the L forms give LTIME (a 32-bit point meets an L
  /// one as an L one). The difference of the ticks, in the duration's unit, modulo 2^bits: a
  /// later point first gives the time between them; an earlier one wraps (CODESYS: "negative
  /// TIME values are undefined"), and so does a difference beyond TIME's 49 days
  /// (D#2026-03-01 - D#2026-01-01 is not T#59d).
  friend constexpr duration operator-(basic_time_point a, basic_time_point b) noexcept {
    return as_duration(static_cast<Rep>(std::uint64_t{a.value_} - b.value_));
  }

  /// TOD + TIME = TOD, DT + TIME = DT, LTOD + LTIME = LTOD, LDT + LTIME = LDT (a TIME widens to
  /// LTIME): the duration's ticks, truncated to the point's (DT counts seconds: DT + T#1500ms
  /// adds 1 s), added modulo 2^bits. No wrap at midnight: a TOD past 24 hours holds the hours
  /// past it (TOD#23:00:00 + T#2h holds 25 h).
  friend constexpr basic_time_point operator+(basic_time_point a, duration t) noexcept
    requires(Kind != time_point_kind::date)
  {
    return from_ticks(static_cast<Rep>(std::uint64_t{a.value_} + duration_ticks(t)));
  }
  /// TOD - TIME = TOD, DT - TIME = DT (and the L forms), modulo 2^bits: DT#1970-01-01-00:00:00
  /// - T#1s is DT#2106-02-07-06:28:15.
  friend constexpr basic_time_point operator-(basic_time_point a, duration t) noexcept
    requires(Kind != time_point_kind::date)
  {
    return from_ticks(static_cast<Rep>(std::uint64_t{a.value_} - duration_ticks(t)));
  }

  /// `tod += t` is ST's `tod := tod + t` (TOD and DT, with a duration of their width or TIME).
  template <class D>
    requires(Kind != time_point_kind::date && detail::is_time<D>::value && sizeof(D) <= sizeof(Rep))
  constexpr basic_time_point& operator+=(D t) noexcept {
    value_ = static_cast<Rep>(std::uint64_t{value_} + duration_ticks(t));
    return *this;
  }
  template <class D>
    requires(Kind != time_point_kind::date && detail::is_time<D>::value && sizeof(D) <= sizeof(Rep))
  constexpr basic_time_point& operator-=(D t) noexcept {
    value_ = static_cast<Rep>(std::uint64_t{value_} - duration_ticks(t));
    return *this;
  }

  /// A duration as a number of this type's ticks, truncated (DT + T#1500ms adds 1 s), modulo
  /// 2^bits.
  template <class D>
  static constexpr Rep duration_ticks(D t) noexcept {
    using ratio = std::ratio_divide<typename D::period, Period>;
    return static_cast<Rep>(static_cast<std::uint64_t>(t.count()) * static_cast<std::uint64_t>(ratio::num) /
                            static_cast<std::uint64_t>(ratio::den));
  }
  /// A number of this type's ticks as a duration of its width, modulo 2^bits (DT - DT: the
  /// seconds times 1000 in a TIME).
  static constexpr duration as_duration(Rep ticks) noexcept {
    using ratio = std::ratio_divide<Period, typename duration::period>;
    return duration::from_ticks(
        static_cast<typename duration::rep>(static_cast<std::uint64_t>(ticks) * static_cast<std::uint64_t>(ratio::num) /
                                            static_cast<std::uint64_t>(ratio::den)));
  }

 private:
  friend struct detail::scalar_access;
  Rep value_ = 0;
};

template <class Rep, class Period, time_point_kind Kind>
struct detail::is_scalar_wrapper<basic_time_point<Rep, Period, Kind>> : std::true_type {};
template <class Rep, class Period, time_point_kind Kind>
struct detail::is_iec_value<basic_time_point<Rep, Period, Kind>> : std::true_type {};

/// IEC DATE as CODESYS stores it: unsigned 32-bit seconds since 1970-01-01.
using DATE = basic_time_point<std::uint32_t, std::ratio<1>, time_point_kind::date>;
/// IEC TIME_OF_DAY as CODESYS stores it: unsigned 32-bit milliseconds since midnight.
using TIME_OF_DAY = basic_time_point<std::uint32_t, std::milli, time_point_kind::time_of_day>;
using TOD = TIME_OF_DAY;
/// IEC DATE_AND_TIME as CODESYS stores it: unsigned 32-bit seconds since 1970-01-01-00:00:00.
using DATE_AND_TIME = basic_time_point<std::uint32_t, std::ratio<1>, time_point_kind::date_and_time>;
using DT = DATE_AND_TIME;
/// IEC LDATE as CODESYS stores it: unsigned 64-bit nanoseconds since 1970-01-01.
using LDATE = basic_time_point<std::uint64_t, std::nano, time_point_kind::date>;
/// IEC LTIME_OF_DAY as CODESYS stores it: unsigned 64-bit nanoseconds since midnight.
using LTIME_OF_DAY = basic_time_point<std::uint64_t, std::nano, time_point_kind::time_of_day>;
using LTOD = LTIME_OF_DAY;
/// IEC LDATE_AND_TIME as CODESYS stores it: unsigned 64-bit nanoseconds since 1970-01-01.
using LDATE_AND_TIME = basic_time_point<std::uint64_t, std::nano, time_point_kind::date_and_time>;
using LDT = LDATE_AND_TIME;

// The names CODESYS's conversions use (DT_TO_DATE, TOD_TO_STRING).
template <>
struct detail::iec_name<DATE> {
  static constexpr std::string_view value = "DATE";
};
template <>
struct detail::iec_name<TOD> {
  static constexpr std::string_view value = "TOD";
};
template <>
struct detail::iec_name<DT> {
  static constexpr std::string_view value = "DT";
};
template <>
struct detail::iec_name<LDATE> {
  static constexpr std::string_view value = "LDATE";
};
template <>
struct detail::iec_name<LTOD> {
  static constexpr std::string_view value = "LTOD";
};
template <>
struct detail::iec_name<LDT> {
  static constexpr std::string_view value = "LDT";
};

/// DATE, TOD, DT, LDATE, LTOD, LDT (IEC ANY_DATE).
template <class T>
concept AnyDate = detail::is_time_point<T>::value;

namespace detail {

/// The point of a sum or difference of the point P and the duration D: P, or P's L form when
/// D is an LTIME (TOD + LTIME = LTOD, DT + LTIME = LDT, as CODESYS's ADD gives).
template <class P, class D>
using point_with_duration_t = std::conditional_t<(sizeof(D) > sizeof(P)), long_point_t<P>, P>;

/// `point + duration` and `point - duration`: TOD and DT (short or long) with TIME or LTIME.
template <class P, class D>
concept point_and_duration = is_time_point<P>::value && P::kind != time_point_kind::date && is_time<D>::value;

/// `point - point` of one kind (either width): a duration.
template <class A, class B>
concept points_of_one_kind = is_time_point<A>::value && is_time_point<B>::value && A::kind == B::kind;

/// The wider of two points of one kind.
template <class A, class B>
using wider_point_t = std::conditional_t<(sizeof(B) > sizeof(A)), B, A>;

/// An operand a point in time may meet in a rejected operation: an IEC value or a C++ number.
template <class X>
concept point_partner = is_iec_value<X>::value || std::is_arithmetic_v<X>;

/// An operation of a point with something, where at least one operand is a point.
template <class A, class B>
concept point_operation = (is_time_point<A>::value || is_time_point<B>::value) && point_partner<A> && point_partner<B>;

/// The result of a rejected operation: it converts to whatever the expression around it
/// wants, so that the rejection is the one error reported.
struct rejected_point_operation {
  template <class T>
  constexpr operator T() const noexcept {  // implicit: no second error after the first
    return T{};
  }
};

template <class Left, class Right>
constexpr void no_point_sum() {
  static_assert(dependent_false<Left, Right>,
                "iecoop: ST adds to a point in time only a duration, and only to TOD and DT (TOD + TIME, DT + TIME, "
                "as CODESYS's ADD allows), never to a DATE; the types spelled in `Left` and `Right` do not add. "
                "Write DATE_TO_DT(d) + t, or subtract two points (d2 - d1) for the TIME between them");
}
template <class Left, class Right>
constexpr void no_point_difference() {
  static_assert(dependent_false<Left, Right>,
                "iecoop: ST subtracts from a point in time only a point of its own kind (DT - DT, DATE - DATE give a "
                "TIME) or, from TOD and DT, a duration (TOD - TIME); the types spelled in `Left` and `Right` do not "
                "subtract. Convert one first, e.g. DT_TO_DATE(dt) or DT_TO_TOD(dt)");
}
template <class Left, class Right>
constexpr void no_point_product() {
  static_assert(dependent_false<Left, Right>,
                "iecoop: a DATE, TOD or DT is a point in time, not a number: ST does not multiply or divide it "
                "(the types spelled in `Left` and `Right`); compute with a TIME, or convert the point first, "
                "e.g. DT_TO_UDINT(dt)");
}

}  // namespace detail

/// TOD + LTIME = LTOD, DT + LTIME = LDT: a 32-bit point meets an LTIME as its L form, as
/// CODESYS's ADD gives. (The other sums and differences are the types' own operators.)
template <class P, class D>
  requires(detail::point_and_duration<P, D> && sizeof(D) > sizeof(P))
constexpr detail::long_point_t<P> operator+(const P& a, const D& t) noexcept {
  return detail::long_point_t<P>(a) + t;
}
/// LTOD#... - LTIME on a TOD: the L form, as for the sum.
template <class P, class D>
  requires(detail::point_and_duration<P, D> && sizeof(D) > sizeof(P))
constexpr detail::long_point_t<P> operator-(const P& a, const D& t) noexcept {
  return detail::long_point_t<P>(a) - t;
}

// What ST does not compute with points in time: rejected with the rule and the fix.
template <class A, class B>
  requires(detail::point_operation<A, B> && !detail::point_and_duration<A, B>)
constexpr detail::rejected_point_operation operator+(const A&, const B&) noexcept {
  detail::no_point_sum<detail::spelled_iec_name_t<A>, detail::spelled_iec_name_t<B>>();
  return {};
}
template <class A, class B>
  requires(detail::point_operation<A, B> && !detail::point_and_duration<A, B> && !detail::points_of_one_kind<A, B>)
constexpr detail::rejected_point_operation operator-(const A&, const B&) noexcept {
  detail::no_point_difference<detail::spelled_iec_name_t<A>, detail::spelled_iec_name_t<B>>();
  return {};
}
template <class A, class B>
  requires detail::point_operation<A, B>
constexpr detail::rejected_point_operation operator*(const A&, const B&) noexcept {
  detail::no_point_product<detail::spelled_iec_name_t<A>, detail::spelled_iec_name_t<B>>();
  return {};
}
template <class A, class B>
  requires detail::point_operation<A, B>
constexpr detail::rejected_point_operation operator/(const A&, const B&) noexcept {
  detail::no_point_product<detail::spelled_iec_name_t<A>, detail::spelled_iec_name_t<B>>();
  return {};
}

}  // namespace iecoop

#include <iecoop/detail/pop_macros.hpp>
