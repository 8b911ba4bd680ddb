// SPDX-License-Identifier: MIT
// iecoop/types/date_time_text.hpp — the IEC text of DATE, TOD, DT and their L forms: parse it
// (D#2026-11-23, TOD#12:30:00.5, DT#2026-11-23-12:30:00, LDT#...-12:30:00.123456789) and
// write it back.
//
// Parsing follows the literals of IEC 61131-3 as CODESYS accepts them: the prefix (D# or DATE#,
// TOD# or TIME_OF_DAY#, DT# or DATE_AND_TIME#, LDATE# or LD#, LTOD# or LTIME_OF_DAY#, LDT# or
// LDATE_AND_TIME#, any case), fields of one or more digits (D#2020-2-7), a fraction of the
// second after '.'. Nothing is guessed: a day the month does not have, an hour above 23, a
// fraction finer than the type resolves, a date outside the type's range are parse errors.
// Writing gives the form CODESYS's *_TO_STRING gives: two-digit fields, a fraction only
// where there is one (TOD#14:01:05.123, TOD#12:30:00.5).
#pragma once

#include <cstddef>
#include <cstdint>
#include <limits>
#include <ratio>
#include <string_view>

#include <iecoop/config.hpp>
#include <iecoop/detail/parse_result.hpp>
#include <iecoop/types/date_time.hpp>
#include <iecoop/types/literal_text.hpp>

#include <iecoop/detail/push_macros.hpp>

namespace iecoop {

namespace detail {

/// The point type a literal prefix names.
enum class point_prefix { none, date, ldate, tod, ltod, dt, ldt };
constexpr point_prefix classify_point_prefix(std::string_view prefix) noexcept {
  if (iequals(prefix, "D") || iequals(prefix, "DATE")) return point_prefix::date;
  if (iequals(prefix, "LD") || iequals(prefix, "LDATE")) return point_prefix::ldate;
  if (iequals(prefix, "TOD") || iequals(prefix, "TIME_OF_DAY")) return point_prefix::tod;
  if (iequals(prefix, "LTOD") || iequals(prefix, "LTIME_OF_DAY")) return point_prefix::ltod;
  if (iequals(prefix, "DT") || iequals(prefix, "DATE_AND_TIME")) return point_prefix::dt;
  if (iequals(prefix, "LDT") || iequals(prefix, "LDATE_AND_TIME")) return point_prefix::ldt;
  return point_prefix::none;
}

/// The prefix names T's own literals, or, for an L form, its 32-bit form's (which widen).
template <class T>
constexpr bool point_prefix_fits(std::string_view prefix) noexcept {
  const point_prefix p = classify_point_prefix(prefix);
  constexpr bool is_long = sizeof(typename T::rep) > 4;
  switch (T::kind) {
    case time_point_kind::date: return p == point_prefix::date || (is_long && p == point_prefix::ldate);
    case time_point_kind::time_of_day: return p == point_prefix::tod || (is_long && p == point_prefix::ltod);
    case time_point_kind::date_and_time: return p == point_prefix::dt || (is_long && p == point_prefix::ldt);
  }
  return false;
}

/// Nanoseconds per tick of T (1'000'000'000 for DATE and DT, 1'000'000 for TOD, 1 for the L forms).
template <class T>
inline constexpr std::uint64_t ns_per_tick =
    static_cast<std::uint64_t>(std::ratio_multiply<typename T::period, std::giga>::num) /
    static_cast<std::uint64_t>(std::ratio_multiply<typename T::period, std::giga>::den);

inline constexpr std::uint64_t ns_per_second = 1'000'000'000;
inline constexpr std::uint64_t ns_per_day = seconds_per_day * ns_per_second;

/// A field of a date or time of day: decimal digits (with '_' between two), at s[i].
constexpr parse_result<std::uint64_t> read_point_field(std::string_view s, std::size_t& i,
                                                       std::size_t offset) noexcept {
  const std::size_t at = i;
  const digit_run run = read_decimal(s, i);
  if (run.error != parse_error::none) return {run.error, offset + run.error_at};
  if (run.overflow) return {parse_error::out_of_range, offset + at};
  return run.value;
}

/// The separator `c` at s[i], which is then skipped.
constexpr bool skip_separator(std::string_view s, std::size_t& i, char c) noexcept {
  if (i >= s.size() || s[i] != c) return false;
  ++i;
  return true;
}

/// "yyyy-mm-dd" at s[i]: the days since 1970-01-01.
constexpr parse_result<std::uint64_t> parse_civil_days(std::string_view s, std::size_t& i,
                                                       std::size_t offset) noexcept {
  const std::size_t year_at = i;
  const auto year = read_point_field(s, i, offset);
  if (!year) return year;
  if (!skip_separator(s, i, '-')) return {parse_error::expected_separator, offset + i};
  const std::size_t month_at = i;
  const auto month = read_point_field(s, i, offset);
  if (!month) return month;
  if (!skip_separator(s, i, '-')) return {parse_error::expected_separator, offset + i};
  const std::size_t day_at = i;
  const auto day = read_point_field(s, i, offset);
  if (!day) return day;
  const std::uint64_t y = year.value_or(0);
  const std::uint64_t m = month.value_or(0);
  const std::uint64_t d = day.value_or(0);
  if (m < 1 || m > 12) return {parse_error::invalid_date, offset + month_at};
  if (d < 1 || d > days_in_month(y, m)) return {parse_error::invalid_date, offset + day_at};
  // Every IEC point counts from 1970; no type reaches the year 10000.
  if (y < 1970 || y > 9999) return {parse_error::out_of_range, offset + year_at};
  return days_from_civil(y, m, d);
}

/// "hh:mm:ss[.fffffffff]" at s[i]: the nanoseconds since midnight, which must be whole
/// multiples of `resolution_ns`.
constexpr parse_result<std::uint64_t> parse_daytime_ns(std::string_view s, std::size_t& i, std::size_t offset,
                                                       std::uint64_t resolution_ns) noexcept {
  const std::size_t hour_at = i;
  const auto hour = read_point_field(s, i, offset);
  if (!hour) return hour;
  if (!skip_separator(s, i, ':')) return {parse_error::expected_separator, offset + i};
  const std::size_t minute_at = i;
  const auto minute = read_point_field(s, i, offset);
  if (!minute) return minute;
  if (!skip_separator(s, i, ':')) return {parse_error::expected_separator, offset + i};
  const std::size_t second_at = i;
  const auto second = read_point_field(s, i, offset);
  if (!second) return second;
  if (hour.value_or(0) > 23) return {parse_error::invalid_time_of_day, offset + hour_at};
  if (minute.value_or(0) > 59) return {parse_error::invalid_time_of_day, offset + minute_at};
  if (second.value_or(0) > 59) return {parse_error::invalid_time_of_day, offset + second_at};
  std::uint64_t ns = ((hour.value_or(0) * 60 + minute.value_or(0)) * 60 + second.value_or(0)) * ns_per_second;
  if (i < s.size() && s[i] == '.') {
    ++i;
    if (i >= s.size() || !is_digit(s[i])) return {parse_error::expected_digit, offset + i};
    std::uint64_t weight = ns_per_second / 10;
    bool last_was_digit = false;
    for (; i < s.size(); ++i) {
      const char c = s[i];
      if (c == '_') {
        if (!last_was_digit || i + 1 >= s.size() || !is_digit(s[i + 1])) {
          return {parse_error::misplaced_underscore, offset + i};
        }
        last_was_digit = false;
        continue;
      }
      if (!is_digit(c)) break;
      const auto digit = static_cast<std::uint64_t>(c - '0');
      if (weight == 0) {
        if (digit != 0) return {parse_error::too_precise, offset + i};  // below 1 ns
      } else {
        if (digit * weight % resolution_ns != 0) return {parse_error::too_precise, offset + i};
        ns += digit * weight;
        weight /= 10;
      }
      last_was_digit = true;
    }
  }
  return ns;
}

}  // namespace detail

/**
 * Parses the IEC text of a point in time into `T` (DATE, TOD, DT, LDATE, LTOD, LDT):
 * `D#2026-11-23`, `DATE#2020-2-7`, `TOD#12:30:00.5`, `DT#2026-11-23-12:30:00`,
 * `LDT#2026-11-23-12:30:00.123456789`. An L form takes its 32-bit form's literal too
 * (`D#...` as an LDATE), as the value widens exactly. Dates start at 1970-01-01 and end where
 * the type does (D#2106-02-07, DT#2106-02-07-06:28:15, LDATE#2554-07-21,
 * LDT#2554-07-21-23:34:33.709551615); a TOD's hour is 0..23; the fraction may not be finer than
 * the type (DT: 1 s, TOD: 1 ms, the L forms: 1 ns).
 */
template <AnyDate T>
[[nodiscard]] constexpr parse_result<T> parse_time_point(std::string_view text) noexcept {
  using rep = typename T::rep;
  constexpr std::uint64_t tick = detail::ns_per_tick<T>;
  if (text.empty()) return {parse_error::empty, 0};
  const detail::prefixed p = detail::split_prefix(text);
  if (p.prefix.empty()) return {parse_error::missing_prefix, 0};
  if (!detail::point_prefix_fits<T>(p.prefix)) return {parse_error::wrong_prefix, 0};
  const std::string_view s = p.body;
  const std::size_t offset = p.body_offset;
  if (s.empty()) return {parse_error::no_value, offset};
  std::size_t i = 0;
  std::uint64_t days = 0;
  std::uint64_t daytime_ns = 0;
  if constexpr (T::kind != time_point_kind::time_of_day) {
    const auto d = detail::parse_civil_days(s, i, offset);
    if (!d) return {d.error(), d.position()};
    days = d.value_or(0);
  }
  if constexpr (T::kind == time_point_kind::date_and_time) {
    if (!detail::skip_separator(s, i, '-')) return {parse_error::expected_separator, offset + i};
  }
  if constexpr (T::kind != time_point_kind::date) {
    const auto ns = detail::parse_daytime_ns(s, i, offset, tick);
    if (!ns) return {ns.error(), ns.position()};
    daytime_ns = ns.value_or(0);
  }
  if (i != s.size()) return {parse_error::trailing_characters, offset + i};
  // The ticks: the days' (each a whole number of ticks) plus the time of day's.
  std::uint64_t ticks = 0;
  if (!detail::mul_add(days, detail::ns_per_day / tick, daytime_ns / tick, ticks) ||
      ticks > std::numeric_limits<rep>::max()) {
    return {parse_error::out_of_range, offset};
  }
  return T::from_ticks(static_cast<rep>(ticks));
}

/// Parses a DATE: `D#2026-11-23`, `DATE#2020-2-7`.
[[nodiscard]] constexpr parse_result<DATE> parse_date(std::string_view text) noexcept {
  return parse_time_point<DATE>(text);
}
/// Parses an LDATE: `LDATE#2300-01-01`, `LD#2026-11-23`, or a DATE literal.
[[nodiscard]] constexpr parse_result<LDATE> parse_ldate(std::string_view text) noexcept {
  return parse_time_point<LDATE>(text);
}
/// Parses a TIME_OF_DAY: `TOD#12:30:00`, `TIME_OF_DAY#8:0:0.25`.
[[nodiscard]] constexpr parse_result<TOD> parse_tod(std::string_view text) noexcept {
  return parse_time_point<TOD>(text);
}
/// Parses an LTIME_OF_DAY: `LTOD#12:30:00.123456789`, or a TOD literal.
[[nodiscard]] constexpr parse_result<LTOD> parse_ltod(std::string_view text) noexcept {
  return parse_time_point<LTOD>(text);
}
/// Parses a DATE_AND_TIME: `DT#2026-11-23-12:30:00`, `DATE_AND_TIME#2020-2-7-12:55:1`.
[[nodiscard]] constexpr parse_result<DT> parse_dt(std::string_view text) noexcept { return parse_time_point<DT>(text); }
/// Parses an LDATE_AND_TIME: `LDT#2026-11-23-12:30:00.5`, or a DT literal.
[[nodiscard]] constexpr parse_result<LDT> parse_ldt(std::string_view text) noexcept {
  return parse_time_point<LDT>(text);
}

// ---------------------------------------------------------------------------------------
// Formatting (see to_text in <iecoop/types/literal_text.hpp>)

template <>
inline constexpr std::size_t max_text_length<DATE> = 12;  // D#2106-02-07
template <>
inline constexpr std::size_t max_text_length<LDATE> = 16;  // LDATE#2554-07-21
// A TOD holds up to 2^32 - 1 ms (past midnight, as CODESYS's DWORD arithmetic leaves it), and
// its text then shows the hours: TOD#1193:02:47.295.
template <>
inline constexpr std::size_t max_text_length<TOD> = 18;
template <>
inline constexpr std::size_t max_text_length<LTOD> = 28;  // LTOD#5124095:34:33.709551615
template <>
inline constexpr std::size_t max_text_length<DT> = 22;  // DT#2106-02-07-06:28:15
template <>
inline constexpr std::size_t max_text_length<LDT> = 33;  // LDT#2554-07-21-23:34:33.709551615

namespace detail {

/// `v` in decimal with at least `width` digits (leading zeros).
constexpr char* write_padded(char* out, std::uint64_t v, std::size_t width) noexcept {
  char digits[20]{};
  std::size_t n = 0;
  do {
    digits[n++] = static_cast<char>('0' + v % 10);
    v /= 10;
  } while (v != 0);
  while (n < width) digits[n++] = '0';
  while (n > 0) *out++ = digits[--n];
  return out;
}

/// yyyy-mm-dd of the day `days` after 1970-01-01.
constexpr char* write_civil(char* out, std::uint64_t days) noexcept {
  const civil_date c = civil_from_days(days);
  out = write_padded(out, c.year, 4);
  *out++ = '-';
  out = write_padded(out, c.month, 2);
  *out++ = '-';
  return write_padded(out, c.day, 2);
}

/// hh:mm:ss of `ns` after midnight (the hours past 23 where there are), then '.' and at most
/// `fraction_digits` digits of the second, without trailing zeros, where they are not all 0.
constexpr char* write_daytime(char* out, std::uint64_t ns, std::size_t fraction_digits) noexcept {
  const std::uint64_t seconds = ns / ns_per_second;
  out = write_padded(out, seconds / 3600, 2);
  *out++ = ':';
  out = write_padded(out, seconds / 60 % 60, 2);
  *out++ = ':';
  out = write_padded(out, seconds % 60, 2);
  std::uint64_t fraction = ns % ns_per_second;
  if (fraction_digits == 0 || fraction == 0) return out;
  char digits[9]{};
  for (std::size_t k = 9; k > 0; --k) {
    digits[k - 1] = static_cast<char>('0' + fraction % 10);
    fraction /= 10;
  }
  std::size_t n = fraction_digits;
  while (n > 0 && digits[n - 1] == '0') --n;
  *out++ = '.';
  for (std::size_t k = 0; k < n; ++k) *out++ = digits[k];
  return out;
}

template <class T>
constexpr std::string_view point_text_prefix() noexcept {
  constexpr bool is_long = sizeof(typename T::rep) > 4;
  switch (T::kind) {
    case time_point_kind::date: return is_long ? "LDATE#" : "D#";
    case time_point_kind::time_of_day: return is_long ? "LTOD#" : "TOD#";
    case time_point_kind::date_and_time: return is_long ? "LDT#" : "DT#";
  }
  return {};
}

}  // namespace detail

/// `D#2026-11-23`, `TOD#12:30:00.5`, `DT#2026-11-23-12:30:00`, `LDATE#...`, `LTOD#...`,
/// `LDT#...` (at most max_text_length<T> characters). A DATE shows its day only (a DATE that
/// holds seconds past midnight, as UDINT_TO_DATE can make one, shows the day they fall in); a
/// TOD past midnight shows its hours past 23 (TOD#25:00:00), which parsing rejects.
template <AnyDate T>
constexpr char* to_text(char* out, T value) noexcept {
  constexpr std::uint64_t tick = detail::ns_per_tick<T>;
  constexpr std::uint64_t ticks_per_day = detail::ns_per_day / tick;
  constexpr std::size_t fraction_digits = tick >= detail::ns_per_second ? 0 : tick == 1 ? 9 : 3;
  const std::uint64_t ticks = value.count();
  out = detail::write(out, detail::point_text_prefix<T>());
  if constexpr (T::kind == time_point_kind::time_of_day) {
    return detail::write_daytime(out, ticks * tick, fraction_digits);
  } else {
    out = detail::write_civil(out, ticks / ticks_per_day);
    if constexpr (T::kind == time_point_kind::date_and_time) {
      *out++ = '-';
      out = detail::write_daytime(out, ticks % ticks_per_day * tick, fraction_digits);
    }
    return out;
  }
}

}  // namespace iecoop

#include <iecoop/detail/pop_macros.hpp>
