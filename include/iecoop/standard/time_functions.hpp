// SPDX-License-Identifier: MIT
// iecoop/standard/time_functions.hpp — IEC 61131-3's functions of time data types (ed. 3,
// tables 36 and 37): ADD_TIME .. DIV_LTIME, CONCAT_DATE_TOD, CONCAT_DATE .. CONCAT_LDT,
// SPLIT_DATE .. SPLIT_LDT and DAY_OF_WEEK.
//
//     dtEnd := ADD_DT_TIME(dtStart, T#90m);          dtEnd = ADD_DT_TIME(dtStart, "T#90m"_iec);
//     tTaken := SUB_DT_DT(dtEnd, dtStart);           tTaken = SUB_DT_DT(dtEnd, dtStart);
//     dtAt := CONCAT_DT(2026, 11, 23, 12, 30, 0, 0); dtAt = CONCAT_DT(2026, 11, 23, 12, 30, 0, 0);
//     SPLIT_DATE(IN := d, YEAR => iY,                SPLIT_DATE(d, iY, iM, iD);
//                MONTH => iM, DAY => iD);
//
// ADD_* and SUB_* compute as the operators do (date_time.hpp): modulo 2^32 or 2^64, with no
// wrap at midnight. CONCAT_* take ANY_INT components and check them: a month outside 1..12, a
// day the month does not have, an hour above 23, a minute or second above 59, a millisecond
// above 999, or a result outside the type's range report fault_kind::invalid_value, and the
// result is then the type's zero (D#1970-01-01, TOD#00:00:00, DT#1970-01-01-00:00:00). SPLIT_*
// write ANY_INT variables; one too narrow for its value (a SINT for the year) reports
// fault_kind::invalid_value and keeps the low bytes. DAY_OF_WEEK gives 0 for Sunday to 6 for
// Saturday, as IEC defines it.
#pragma once

#include <cstdint>
#include <limits>
#include <type_traits>
#include <utility>

#include <iecoop/config.hpp>
#include <iecoop/fault.hpp>
#include <iecoop/standard/detail/generic_arguments.hpp>
#include <iecoop/types/date_time.hpp>
#include <iecoop/types/date_time_text.hpp>
#include <iecoop/types/detail/value_operators.hpp>
#include <iecoop/types/elementary.hpp>
#include <iecoop/types/time.hpp>

#include <iecoop/detail/push_macros.hpp>

namespace iecoop {

// --- Table 36: arithmetic on durations and points in time --------------------------------

/// ADD_TIME(IN1, IN2): IN1 + IN2, modulo 2^32 ms.
[[nodiscard]] constexpr TIME ADD_TIME(TIME in1, TIME in2) noexcept { return in1 + in2; }
/// ADD_LTIME(IN1, IN2): IN1 + IN2, modulo 2^64 ns.
[[nodiscard]] constexpr LTIME ADD_LTIME(LTIME in1, LTIME in2) noexcept { return in1 + in2; }
/// ADD_TOD_TIME(IN1, IN2): the time of day IN2 after IN1 (no wrap at midnight).
[[nodiscard]] constexpr TOD ADD_TOD_TIME(TOD in1, TIME in2) noexcept { return in1 + in2; }
/// ADD_LTOD_LTIME(IN1, IN2): the time of day IN2 after IN1 (no wrap at midnight).
[[nodiscard]] constexpr LTOD ADD_LTOD_LTIME(LTOD in1, LTIME in2) noexcept { return in1 + in2; }
/// ADD_DT_TIME(IN1, IN2): IN2 after IN1, in whole seconds (the milliseconds of IN2 are dropped).
[[nodiscard]] constexpr DT ADD_DT_TIME(DT in1, TIME in2) noexcept { return in1 + in2; }
/// ADD_LDT_LTIME(IN1, IN2): IN2 after IN1.
[[nodiscard]] constexpr LDT ADD_LDT_LTIME(LDT in1, LTIME in2) noexcept { return in1 + in2; }

/// SUB_TIME(IN1, IN2): IN1 - IN2, modulo 2^32 ms.
[[nodiscard]] constexpr TIME SUB_TIME(TIME in1, TIME in2) noexcept { return in1 - in2; }
/// SUB_LTIME(IN1, IN2): IN1 - IN2, modulo 2^64 ns.
[[nodiscard]] constexpr LTIME SUB_LTIME(LTIME in1, LTIME in2) noexcept { return in1 - in2; }
/// SUB_DATE_DATE(IN1, IN2): the TIME from IN2 to IN1 (wraps beyond 49 days, as in CODESYS).
[[nodiscard]] constexpr TIME SUB_DATE_DATE(DATE in1, DATE in2) noexcept { return in1 - in2; }
/// SUB_LDATE_LDATE(IN1, IN2): the LTIME from IN2 to IN1.
[[nodiscard]] constexpr LTIME SUB_LDATE_LDATE(LDATE in1, LDATE in2) noexcept { return in1 - in2; }
/// SUB_TOD_TIME(IN1, IN2): the time of day IN2 before IN1 (modulo 2^32 ms, no wrap at midnight).
[[nodiscard]] constexpr TOD SUB_TOD_TIME(TOD in1, TIME in2) noexcept { return in1 - in2; }
/// SUB_LTOD_LTIME(IN1, IN2): the time of day IN2 before IN1.
[[nodiscard]] constexpr LTOD SUB_LTOD_LTIME(LTOD in1, LTIME in2) noexcept { return in1 - in2; }
/// SUB_TOD_TOD(IN1, IN2): the TIME from IN2 to IN1.
[[nodiscard]] constexpr TIME SUB_TOD_TOD(TOD in1, TOD in2) noexcept { return in1 - in2; }
/// SUB_LTOD_LTOD(IN1, IN2): the LTIME from IN2 to IN1.
[[nodiscard]] constexpr LTIME SUB_LTOD_LTOD(LTOD in1, LTOD in2) noexcept { return in1 - in2; }
/// SUB_DT_TIME(IN1, IN2): IN2 before IN1, in whole seconds.
[[nodiscard]] constexpr DT SUB_DT_TIME(DT in1, TIME in2) noexcept { return in1 - in2; }
/// SUB_LDT_LTIME(IN1, IN2): IN2 before IN1.
[[nodiscard]] constexpr LDT SUB_LDT_LTIME(LDT in1, LTIME in2) noexcept { return in1 - in2; }
/// SUB_DT_DT(IN1, IN2): the TIME from IN2 to IN1 (wraps beyond 49 days, as in CODESYS).
[[nodiscard]] constexpr TIME SUB_DT_DT(DT in1, DT in2) noexcept { return in1 - in2; }
/// SUB_LDT_LDT(IN1, IN2): the LTIME from IN2 to IN1.
[[nodiscard]] constexpr LTIME SUB_LDT_LDT(LDT in1, LDT in2) noexcept { return in1 - in2; }

namespace detail {
/// A factor of MUL_TIME and DIV_TIME: a number, or a variable of one.
template <class N>
concept time_factor_argument = duration_factor<argument_t<N>>;
}  // namespace detail

/// MUL_TIME(IN1, IN2): IN1 * IN2 (ANY_NUM); integer factors wrap, REAL ones round to the ms.
template <detail::time_factor_argument N>
[[nodiscard]] constexpr TIME MUL_TIME(TIME in1, const N& in2) noexcept {
  return in1 * detail::argument_value(in2);
}
/// MUL_LTIME(IN1, IN2): IN1 * IN2 (ANY_NUM).
template <detail::time_factor_argument N>
[[nodiscard]] constexpr LTIME MUL_LTIME(LTIME in1, const N& in2) noexcept {
  return in1 * detail::argument_value(in2);
}
/// DIV_TIME(IN1, IN2): IN1 / IN2 (ANY_NUM), truncated; by 0 fault_kind::division_by_zero and T#0ms.
template <detail::time_factor_argument N>
[[nodiscard]] constexpr TIME DIV_TIME(TIME in1, const N& in2) {
  return in1 / detail::argument_value(in2);
}
/// DIV_LTIME(IN1, IN2): IN1 / IN2 (ANY_NUM); by 0 fault_kind::division_by_zero and LTIME#0ns.
template <detail::time_factor_argument N>
[[nodiscard]] constexpr LTIME DIV_LTIME(LTIME in1, const N& in2) {
  return in1 / detail::argument_value(in2);
}

/// CONCAT_DATE_TOD(IN1, IN2): the DT of the day IN1 at the time of day IN2 (a TOD past
/// midnight runs into the next day; modulo 2^32 s).
[[nodiscard]] constexpr DT CONCAT_DATE_TOD(DATE in1, TOD in2) noexcept {
  const std::uint64_t day = in1.count() - in1.count() % detail::seconds_per_day;
  return DT::from_ticks(static_cast<std::uint32_t>(day + in2.count() / 1000));
}
/// CONCAT_LDATE_LTOD(IN1, IN2): the LDT of the day IN1 at the time of day IN2.
[[nodiscard]] constexpr LDT CONCAT_LDATE_LTOD(LDATE in1, LTOD in2) noexcept {
  const std::uint64_t day = in1.count() - in1.count() % detail::ns_per_day;
  return LDT::from_ticks(day + in2.count());
}

// --- Table 37: composing and splitting points in time ------------------------------------

namespace detail {

/// An input of CONCAT_*: an integer (ANY_INT, a C++ integer, an intermediate result, or a
/// variable of one).
template <class X>
concept time_component = cpp_integer<std::remove_cvref_t<X>> || AnyInt<argument_t<X>> || Intermediate<argument_t<X>>;

template <class... X>
constexpr void check_time_components() noexcept {
  static_assert((time_component<X> && ...),
                "iecoop: the inputs of CONCAT_DATE, CONCAT_TOD and CONCAT_DT are integers (ANY_INT), as in "
                "IEC 61131-3; convert other values first, e.g. WORD_TO_UINT(w)");
}

/// A component's value; a ULINT above 2^63 becomes negative, and so invalid.
template <class X>
constexpr std::int64_t component_value(const X& x) noexcept {
  if constexpr (cpp_integer<std::remove_cvref_t<X>>) {
    return static_cast<std::int64_t>(x);
  } else {
    return static_cast<std::int64_t>(argument_value(x).value());
  }
}

/// Components of a point in time; `valid` is false where one is out of its range.
struct time_components {
  std::uint64_t days = 0;    // since 1970-01-01
  std::uint64_t day_ns = 0;  // since midnight
  bool valid = true;
};

constexpr bool in_closed(std::int64_t v, std::int64_t lo, std::int64_t hi) noexcept { return v >= lo && v <= hi; }

constexpr void add_date(time_components& c, std::int64_t y, std::int64_t m, std::int64_t d) noexcept {
  if (!in_closed(y, 1970, 9999) || !in_closed(m, 1, 12) || d < 1 ||
      static_cast<std::uint64_t>(d) > days_in_month(static_cast<std::uint64_t>(y), static_cast<std::uint64_t>(m))) {
    c.valid = false;
    return;
  }
  c.days = days_from_civil(static_cast<std::uint64_t>(y), static_cast<std::uint64_t>(m), static_cast<std::uint64_t>(d));
}

constexpr void add_daytime(time_components& c, std::int64_t h, std::int64_t mi, std::int64_t s,
                           std::int64_t ms) noexcept {
  if (!in_closed(h, 0, 23) || !in_closed(mi, 0, 59) || !in_closed(s, 0, 59) || !in_closed(ms, 0, 999)) {
    c.valid = false;
    return;
  }
  c.day_ns = static_cast<std::uint64_t>(((h * 60 + mi) * 60 + s) * 1000 + ms) * 1'000'000;
}

/// The point T of the components, or T's zero after a fault where they are invalid or out of
/// T's range. `message` names the function and its fallback.
template <class T>
constexpr T point_of(const time_components& c, const char* message) {
  constexpr std::uint64_t tick = ns_per_tick<T>;
  std::uint64_t ticks = 0;
  if (c.valid && mul_add(c.days, ns_per_day / tick, c.day_ns / tick, ticks) &&
      ticks <= std::numeric_limits<typename T::rep>::max()) {
    return T::from_ticks(static_cast<typename T::rep>(ticks));
  }
  fault(fault_kind::invalid_value, message);
  return T{};
}

/// Stores a component in an output variable of an ANY_INT type; a value it cannot hold is a
/// fault, and its low bytes are kept.
template <class Out>
constexpr void store_component(Out& out, std::uint64_t value) {
  using T = unwrapped_t<Out>;
  static_assert(AnyInt<T>,
                "iecoop: the outputs of SPLIT_DATE, SPLIT_TOD and SPLIT_DT are integer variables (ANY_INT), as in "
                "IEC 61131-3; pass e.g. an INT or a UDINT variable");
  if constexpr (AnyInt<T>) {
    using rep = typename T::rep;
    if (!std::in_range<rep>(value)) {
      fault(fault_kind::invalid_value,
            "SPLIT_*: an output variable is too narrow for its value; the low bytes are kept");
    }
    out = T(static_cast<rep>(value));
  }
}

template <class Y, class M, class D>
constexpr void split_days(std::uint64_t days, Y& year, M& month, D& day) {
  const civil_date c = civil_from_days(days);
  store_component(year, c.year);
  store_component(month, c.month);
  store_component(day, c.day);
}

/// SPLIT of a time of day: hours (past 23 for a TOD past midnight), minutes, seconds, ms.
template <class H, class Mi, class S, class Ms>
constexpr void split_daytime(std::uint64_t ns, H& hour, Mi& minute, S& second, Ms& millisecond) {
  const std::uint64_t ms = ns / 1'000'000;
  store_component(hour, ms / 3'600'000);
  store_component(minute, ms / 60'000 % 60);
  store_component(second, ms / 1000 % 60);
  store_component(millisecond, ms % 1000);
}

/// CONCAT_TOD and CONCAT_LTOD: the point P of a time of day, or a fault with `invalid`.
template <class P, class H, class Mi, class S, class Ms>
constexpr P concat_daytime(const H& hour, const Mi& minute, const S& second, const Ms& millisecond,
                           const char* invalid) {
  time_components c;
  add_daytime(c, component_value(hour), component_value(minute), component_value(second), component_value(millisecond));
  return point_of<P>(c, invalid);
}

}  // namespace detail

/// CONCAT_DATE(YEAR, MONTH, DAY): the DATE; invalid or out of range (1970-01-01 ..
/// 2106-02-07): fault_kind::invalid_value and D#1970-01-01.
template <class Y, class M, class D>
[[nodiscard]] constexpr DATE CONCAT_DATE(const Y& year, const M& month, const D& day) {
  detail::check_time_components<Y, M, D>();
  detail::time_components c;
  detail::add_date(c, detail::component_value(year), detail::component_value(month), detail::component_value(day));
  return detail::point_of<DATE>(c, "CONCAT_DATE: no such date, or outside DATE's range; the result is D#1970-01-01");
}

/// CONCAT_TOD(HOUR, MINUTE, SECOND, MILLISECOND): the TIME_OF_DAY; invalid: fault_kind::invalid_value
/// and TOD#00:00:00.
template <class H, class Mi, class S, class Ms>
[[nodiscard]] constexpr TOD CONCAT_TOD(const H& hour, const Mi& minute, const S& second, const Ms& millisecond) {
  detail::check_time_components<H, Mi, S, Ms>();
  return detail::concat_daytime<TOD>(hour, minute, second, millisecond,
                                     "CONCAT_TOD: no such time of day; the result is TOD#00:00:00");
}

/// CONCAT_LTOD(HOUR, MINUTE, SECOND, MILLISECOND): the LTIME_OF_DAY; invalid:
/// fault_kind::invalid_value and LTOD#00:00:00.
template <class H, class Mi, class S, class Ms>
[[nodiscard]] constexpr LTOD CONCAT_LTOD(const H& hour, const Mi& minute, const S& second, const Ms& millisecond) {
  detail::check_time_components<H, Mi, S, Ms>();
  return detail::concat_daytime<LTOD>(hour, minute, second, millisecond,
                                      "CONCAT_LTOD: no such time of day; the result is LTOD#00:00:00");
}

/// CONCAT_DT(YEAR, MONTH, DAY, HOUR, MINUTE, SECOND, MILLISECOND): the DATE_AND_TIME (whole
/// seconds: the milliseconds, 0..999, are dropped); invalid or beyond DT#2106-02-07-06:28:15:
/// fault_kind::invalid_value and DT#1970-01-01-00:00:00.
template <class Y, class Mo, class D, class H, class Mi, class S, class Ms>
[[nodiscard]] constexpr DT CONCAT_DT(const Y& year, const Mo& month, const D& day, const H& hour, const Mi& minute,
                                     const S& second, const Ms& millisecond) {
  detail::check_time_components<Y, Mo, D, H, Mi, S, Ms>();
  detail::time_components c;
  detail::add_date(c, detail::component_value(year), detail::component_value(month), detail::component_value(day));
  detail::add_daytime(c, detail::component_value(hour), detail::component_value(minute),
                      detail::component_value(second), detail::component_value(millisecond));
  c.day_ns -= c.day_ns % detail::ns_per_second;
  return detail::point_of<DT>(c,
                              "CONCAT_DT: no such date or time of day, or outside DT's range; the result is "
                              "DT#1970-01-01-00:00:00");
}

/// CONCAT_LDT(YEAR, MONTH, DAY, HOUR, MINUTE, SECOND, MILLISECOND): the LDATE_AND_TIME;
/// invalid or beyond LDT#2554-07-21-23:34:33.709551615: fault_kind::invalid_value and
/// LDT#1970-01-01-00:00:00.
template <class Y, class Mo, class D, class H, class Mi, class S, class Ms>
[[nodiscard]] constexpr LDT CONCAT_LDT(const Y& year, const Mo& month, const D& day, const H& hour, const Mi& minute,
                                       const S& second, const Ms& millisecond) {
  detail::check_time_components<Y, Mo, D, H, Mi, S, Ms>();
  detail::time_components c;
  detail::add_date(c, detail::component_value(year), detail::component_value(month), detail::component_value(day));
  detail::add_daytime(c, detail::component_value(hour), detail::component_value(minute),
                      detail::component_value(second), detail::component_value(millisecond));
  return detail::point_of<LDT>(c,
                               "CONCAT_LDT: no such date or time of day, or outside LDT's range; the result is "
                               "LDT#1970-01-01-00:00:00");
}

/// SPLIT_DATE(IN, YEAR, MONTH, DAY): the calendar fields of a DATE (or LDATE) into ANY_INT
/// variables.
template <class Y, class M, class D>
constexpr void SPLIT_DATE(LDATE in, Y& year, M& month, D& day) {
  detail::split_days(in.count() / detail::ns_per_day, year, month, day);
}

/// SPLIT_TOD(IN, HOUR, MINUTE, SECOND, MILLISECOND): the fields of a TIME_OF_DAY (the hours
/// past 23 of a TOD past midnight).
template <class H, class Mi, class S, class Ms>
constexpr void SPLIT_TOD(TOD in, H& hour, Mi& minute, S& second, Ms& millisecond) {
  detail::split_daytime(std::uint64_t{in.count()} * 1'000'000, hour, minute, second, millisecond);
}

/// SPLIT_LTOD(IN, HOUR, MINUTE, SECOND, MILLISECOND): the fields of an LTIME_OF_DAY, to the
/// millisecond (as IEC defines it: finer parts are dropped).
template <class H, class Mi, class S, class Ms>
constexpr void SPLIT_LTOD(LTOD in, H& hour, Mi& minute, S& second, Ms& millisecond) {
  detail::split_daytime(in.count(), hour, minute, second, millisecond);
}

/// SPLIT_DT(IN, YEAR, MONTH, DAY, HOUR, MINUTE, SECOND, MILLISECOND): the fields of a
/// DATE_AND_TIME (MILLISECOND is 0: a DT counts whole seconds).
template <class Y, class Mo, class D, class H, class Mi, class S, class Ms>
constexpr void SPLIT_DT(DT in, Y& year, Mo& month, D& day, H& hour, Mi& minute, S& second, Ms& millisecond) {
  detail::split_days(in.count() / detail::seconds_per_day, year, month, day);
  detail::split_daytime(in.count() % detail::seconds_per_day * detail::ns_per_second, hour, minute, second,
                        millisecond);
}

/// SPLIT_LDT(IN, YEAR, MONTH, DAY, HOUR, MINUTE, SECOND, MILLISECOND): the fields of an
/// LDATE_AND_TIME, to the millisecond.
template <class Y, class Mo, class D, class H, class Mi, class S, class Ms>
constexpr void SPLIT_LDT(LDT in, Y& year, Mo& month, D& day, H& hour, Mi& minute, S& second, Ms& millisecond) {
  detail::split_days(in.count() / detail::ns_per_day, year, month, day);
  detail::split_daytime(in.count() % detail::ns_per_day, hour, minute, second, millisecond);
}

/// DAY_OF_WEEK(IN): the day of the week of a DATE (or LDATE): 0 Sunday, 1 Monday .. 6
/// Saturday (1970-01-01 was a Thursday: 4).
[[nodiscard]] constexpr USINT DAY_OF_WEEK(LDATE in) noexcept {
  return USINT(static_cast<std::uint8_t>((in.count() / detail::ns_per_day + 4) % 7));
}

}  // namespace iecoop

#include <iecoop/detail/pop_macros.hpp>
