// SPDX-License-Identifier: MIT
// iecoop/types/literal_text.hpp — IEC literal text: parse values written as in ST (T#1h2m3s4ms, 16#FF,
// INT#-5, TRUE) and format values back into that form.
//
// Parsing never guesses: text that is not a valid literal gives a parse_result holding a
// parse_error and the position where the text went wrong, never a silent 0. Everything
// except REAL/LREAL is constexpr; <iecoop/types/literals.hpp> uses the same parsers at compile
// time.
#pragma once

#include <charconv>  // also std::errc, which from_chars reports (not <system_error>: its <stdexcept> and <string>)
#include <concepts>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <numeric>
#include <string_view>
#include <type_traits>

#include <iecoop/config.hpp>
#include <iecoop/detail/constant_division.hpp>
#include <iecoop/detail/diagnostics.hpp>
#include <iecoop/detail/parse_result.hpp>
#include <iecoop/fault.hpp>
#include <iecoop/types/elementary.hpp>
#include <iecoop/types/time.hpp>

#include <iecoop/detail/push_macros.hpp>

namespace iecoop {

/// Why text is not a valid IEC literal of the requested type.
enum class parse_error : std::uint8_t {
  none,                  ///< no error
  empty,                 ///< the text is empty
  missing_prefix,        ///< a duration or point in time needs its prefix: T#, LTIME#, D#, TOD#, DT#...
  wrong_prefix,          ///< the type prefix names another type (LTIME# where TIME is wanted)
  no_value,              ///< nothing follows the '#'
  expected_digit,        ///< a digit was expected here
  misplaced_underscore,  ///< '_' may only separate two digits, or a unit and the next number
  missing_unit,          ///< a duration number without unit (d, h, m, s, ms, us, ns)
  unknown_unit,          ///< not one of d, h, m, s, ms, us, ns
  unit_order,            ///< units must appear once each, in the order d h m s ms us ns
  unit_overflow,         ///< only the first (highest) unit may exceed its natural range
  fraction_not_last,     ///< only the last unit may have a fraction (T#1.5s, not T#1.5s2ms)
  too_precise,           ///< finer than the type resolves (below 1 ms for TIME, 1 ns for LTIME)
  out_of_range,          ///< the value does not fit the type
  negative,              ///< TIME and LTIME are unsigned (CODESYS), unsigned types too
  invalid_digit,         ///< a digit not valid in the literal's base
  invalid_base,          ///< bases are 2#, 8#, 10# and 16#
  trailing_characters,   ///< text after a complete literal
  expected_separator,    ///< a date or time of day needs '-' between its fields, ':' in the time
  invalid_date,          ///< no such day: a month outside 1..12, a day past the month's end
  invalid_time_of_day,   ///< an hour above 23, a minute or second above 59
  unknown_component,     ///< a name that is no component of the enumeration (parse_enum)
};

/// A one-line description of a parse error.
[[nodiscard]] constexpr const char* describe(parse_error error) noexcept {
  switch (error) {
    case parse_error::none: return "no error";
    case parse_error::empty: return "empty text";
    case parse_error::missing_prefix:
      return "the literal needs its type prefix (T#, LTIME#, D#, TOD#, DT#, LDATE#, LTOD#, LDT#)";
    case parse_error::wrong_prefix: return "the type prefix names another type";
    case parse_error::no_value: return "no value after '#'";
    case parse_error::expected_digit: return "a digit was expected";
    case parse_error::misplaced_underscore: return "'_' may only stand between two digits or after a unit";
    case parse_error::missing_unit: return "a number without unit (d, h, m, s, ms, us, ns)";
    case parse_error::unknown_unit: return "unknown unit; the units are d, h, m, s, ms, us, ns";
    case parse_error::unit_order: return "units must appear once each, in the order d, h, m, s, ms, us, ns";
    case parse_error::unit_overflow: return "only the highest unit may overflow (T#100s12ms is valid, T#5m68s is not)";
    case parse_error::fraction_not_last: return "only the last unit may have a fraction";
    case parse_error::too_precise: return "finer than the type's resolution (TIME: 1 ms, LTIME: 1 ns)";
    case parse_error::out_of_range: return "the value does not fit the type";
    case parse_error::negative: return "negative value for an unsigned type (TIME and LTIME are unsigned)";
    case parse_error::invalid_digit: return "a digit not valid in this base";
    case parse_error::invalid_base: return "the base must be 2, 8, 10 or 16";
    case parse_error::trailing_characters: return "unexpected characters after the literal";
    case parse_error::expected_separator: return "a '-' between the date's fields or a ':' in the time of day";
    case parse_error::invalid_date: return "no such date (a month outside 1..12, or a day past the month's end)";
    case parse_error::invalid_time_of_day: return "no such time of day (an hour above 23, a minute or second above 59)";
    case parse_error::unknown_component: return "no component of the enumeration has this name";
  }
  return "unknown parse error";
}

/// The result of parsing text as a `T`: the value, or the parse_error and the offset in the
/// text where it was found (see basic_parse_result).
template <class T>
using parse_result = basic_parse_result<T, parse_error>;

namespace detail {

constexpr char to_upper(char c) noexcept { return (c >= 'a' && c <= 'z') ? static_cast<char>(c - 'a' + 'A') : c; }
constexpr bool is_digit(char c) noexcept { return c >= '0' && c <= '9'; }
constexpr bool is_letter(char c) noexcept { return (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z'); }

constexpr bool iequals(std::string_view a, std::string_view b) noexcept {
  if (a.size() != b.size()) return false;
  for (std::size_t i = 0; i < a.size(); ++i) {
    if (to_upper(a[i]) != to_upper(b[i])) return false;
  }
  return true;
}

/// a * b + c in uint64, reporting overflow instead of wrapping.
constexpr bool mul_add(std::uint64_t a, std::uint64_t b, std::uint64_t c, std::uint64_t& out) noexcept {
  constexpr std::uint64_t max = std::numeric_limits<std::uint64_t>::max();
  if (b != 0 && a > max / b) return false;
  const std::uint64_t product = a * b;
  if (product > max - c) return false;
  out = product + c;
  return true;
}

/// Splits "PREFIX#rest" at the first '#'; prefix is empty if there is none.
struct prefixed {
  std::string_view prefix;
  std::string_view body;
  std::size_t body_offset;
};
constexpr prefixed split_prefix(std::string_view text) noexcept {
  const std::size_t hash = text.find('#');
  if (hash == std::string_view::npos) return {{}, text, 0};
  return {text.substr(0, hash), text.substr(hash + 1), hash + 1};
}

/// Reads digits (base 10) with single '_' between digits, starting at `i`; accumulates
/// them into `value` (overflow flagged) and the digit count into `digits`.
struct digit_run {
  std::uint64_t value = 0;
  std::size_t digits = 0;
  bool overflow = false;
  parse_error error = parse_error::none;
  std::size_t error_at = 0;
};
constexpr digit_run read_decimal(std::string_view s, std::size_t& i) noexcept {
  digit_run run;
  if (i >= s.size() || !is_digit(s[i])) {
    run.error = (i < s.size() && s[i] == '_') ? parse_error::misplaced_underscore : parse_error::expected_digit;
    run.error_at = i;
    return run;
  }
  while (i < s.size()) {
    if (is_digit(s[i])) {
      if (!run.overflow && !mul_add(run.value, 10, static_cast<std::uint64_t>(s[i] - '0'), run.value))
        run.overflow = true;
      ++run.digits;
      ++i;
    } else if (s[i] == '_') {
      if (i + 1 >= s.size() || !is_digit(s[i + 1])) {
        run.error = parse_error::misplaced_underscore;
        run.error_at = i;
        return run;
      }
      ++i;
    } else {
      break;
    }
  }
  return run;
}

// Duration units, highest first, with their length in nanoseconds and the natural limit
// a unit that is not the first one written must stay below.
struct duration_unit {
  std::string_view name;
  std::uint64_t ns;
  std::uint64_t limit;
};
inline constexpr duration_unit duration_units[] = {
    {"d", 86'400'000'000'000ULL, 0},  // days: only ever the first unit, never limited
    {"h", 3'600'000'000'000ULL, 24}, {"m", 60'000'000'000ULL, 60}, {"s", 1'000'000'000ULL, 60},
    {"ms", 1'000'000ULL, 1000},      {"us", 1'000ULL, 1000},       {"ns", 1ULL, 1000},
};
inline constexpr std::size_t no_unit = sizeof(duration_units) / sizeof(duration_units[0]);

constexpr std::size_t find_unit(std::string_view name) noexcept {
  for (std::size_t u = 0; u < no_unit; ++u) {
    if (iequals(name, duration_units[u].name)) return u;
  }
  return no_unit;
}

/// Parses the part after the prefix ("1h2m3.5s") into nanoseconds; every component must be
/// a whole multiple of `resolution_ns`.
/// With `lenient`, every unit may overflow (to compute what a literal that breaks that rule
/// means, for the diagnostic that proposes its valid spelling).
constexpr parse_result<std::uint64_t> parse_duration_body(std::string_view s, std::size_t offset,
                                                          std::uint64_t resolution_ns, bool lenient = false) noexcept {
  if (s.empty()) return {parse_error::no_value, offset};
  if (s[0] == '-') return {parse_error::negative, offset};
  std::uint64_t total = 0;
  std::size_t i = 0;
  std::size_t previous_unit = no_unit;  // none yet
  bool had_fraction = false;
  while (i < s.size()) {
    const std::size_t number_at = i;
    if (had_fraction) return {parse_error::fraction_not_last, offset + number_at};
    const digit_run whole = read_decimal(s, i);
    if (whole.error != parse_error::none) return {whole.error, offset + whole.error_at};
    digit_run fraction;
    bool has_fraction = false;
    if (i < s.size() && s[i] == '.') {
      ++i;
      has_fraction = true;
      fraction = read_decimal(s, i);
      if (fraction.error != parse_error::none) return {fraction.error, offset + fraction.error_at};
    }
    const std::size_t unit_at = i;
    while (i < s.size() && is_letter(s[i])) ++i;
    if (unit_at == i) return {parse_error::missing_unit, offset + unit_at};
    const std::size_t unit = find_unit(s.substr(unit_at, i - unit_at));
    if (unit == no_unit) return {parse_error::unknown_unit, offset + unit_at};
    if (previous_unit != no_unit && unit <= previous_unit) return {parse_error::unit_order, offset + unit_at};
    if (whole.overflow) return {parse_error::out_of_range, offset + number_at};
    const duration_unit& u = duration_units[unit];
    if (!lenient && previous_unit != no_unit && whole.value >= u.limit)
      return {parse_error::unit_overflow, offset + number_at};
    if (!mul_add(whole.value, u.ns, total, total)) return {parse_error::out_of_range, offset + number_at};
    if (has_fraction) {
      // The fraction D / 10^n of the unit (trailing zeros dropped) adds ns * D / 10^n, which
      // must be a whole number of nanoseconds: the sum, not each digit (LTIME#1.000000000005d
      // is 86400000000432 ns). In lowest terms D' / g, that is: g divides the unit's ns.
      std::uint64_t digits = 0;
      std::uint64_t scale = 1;
      std::size_t significant = 0;  // digits up to the last non-zero one
      std::size_t seen = 0;
      std::size_t k = number_at;
      while (k < s.size() && s[k] != '.') ++k;
      for (std::size_t j = k + 1; j < unit_at; ++j) {
        if (s[j] != '_') {
          ++seen;
          if (s[j] != '0') significant = seen;
        }
      }
      // No unit is finer than 1 ns, and 10^15 divides no unit's length: beyond 14 significant
      // digits a fraction is always too precise.
      if (significant > 14) return {parse_error::too_precise, offset + number_at};
      seen = 0;
      for (std::size_t j = k + 1; j < unit_at && seen < significant; ++j) {
        if (s[j] == '_') continue;
        ++seen;
        digits = digits * 10 + static_cast<std::uint64_t>(s[j] - '0');
        scale *= 10;
      }
      if (digits != 0) {
        const std::uint64_t common = std::gcd(digits, scale);
        const std::uint64_t denominator = scale / common;
        if (u.ns % denominator != 0) return {parse_error::too_precise, offset + number_at};
        if (!mul_add(u.ns / denominator, digits / common, total, total))
          return {parse_error::out_of_range, offset + number_at};
      }
      had_fraction = true;
    }
    // Smaller units can never add up to a whole resolution step again (each stays below
    // its limit), so a component that leaves a remainder makes the literal too precise.
    if (total % resolution_ns != 0) return {parse_error::too_precise, offset + number_at};
    previous_unit = unit;
    if (i < s.size() && s[i] == '_') {
      if (i + 1 >= s.size() || !is_digit(s[i + 1])) return {parse_error::misplaced_underscore, offset + i};
      ++i;
    }
  }
  return total;
}

enum class duration_prefix { none, time, ltime };
constexpr duration_prefix classify_duration_prefix(std::string_view prefix) noexcept {
  if (iequals(prefix, "T") || iequals(prefix, "TIME")) return duration_prefix::time;
  if (iequals(prefix, "LT") || iequals(prefix, "LTIME")) return duration_prefix::ltime;
  return duration_prefix::none;
}

constexpr parse_result<std::uint64_t> parse_duration_ns(std::string_view text, bool accept_ltime,
                                                        std::uint64_t resolution_ns, bool lenient = false) noexcept {
  if (text.empty()) return {parse_error::empty, 0};
  const prefixed p = split_prefix(text);
  if (p.prefix.empty()) return {parse_error::missing_prefix, 0};
  switch (classify_duration_prefix(p.prefix)) {
    case duration_prefix::none: return {parse_error::wrong_prefix, 0};
    case duration_prefix::ltime:
      if (!accept_ltime) return {parse_error::wrong_prefix, 0};
      break;
    case duration_prefix::time: break;
  }
  return parse_duration_body(p.body, p.body_offset, resolution_ns, lenient);
}

}  // namespace detail

/// Parses an IEC TIME literal: `T#1h2m3s4ms`, `TIME#5s`, `t#1.5s`, `T#100s12ms`,
/// `T#1h_30m`. Only the first unit may overflow; the value must be whole milliseconds.
[[nodiscard]] constexpr parse_result<TIME> parse_time(std::string_view text) noexcept {
  const auto ns = detail::parse_duration_ns(text, false, 1'000'000);
  if (!ns) return {ns.error(), ns.position()};
  const std::uint64_t ms = ns.value_or(0) / 1'000'000;
  if (ms > std::numeric_limits<TIME::rep>::max()) return {parse_error::out_of_range, text.find('#') + 1};
  return TIME::from_ticks(static_cast<TIME::rep>(ms));
}

/// Parses an IEC LTIME literal: `LTIME#1ms500us`, `LT#5s`; a TIME literal (`T#5s`) is
/// accepted too, as its value widens exactly.
[[nodiscard]] constexpr parse_result<LTIME> parse_ltime(std::string_view text) noexcept {
  const auto ns = detail::parse_duration_ns(text, true, 1);
  if (!ns) return {ns.error(), ns.position()};
  return LTIME::from_ticks(ns.value_or(0));
}

namespace detail {

/// The duration a TIME or LTIME literal that breaks only "a lower unit may not overflow" stands
/// for ("T#5m68s": T#6m8s), read with every unit allowed to overflow: what the diagnostic of
/// "..."_iec proposes instead (types/literals.hpp). Where the literal is wrong besides (an error
/// further on, "T#5m68s1x"; a duration beyond the type, "T#49d17h2m47s1000ms"), that error.
template <class T>
[[nodiscard]] constexpr parse_result<T> normalized_duration(std::string_view text) noexcept {
  constexpr bool is_ltime = std::is_same_v<T, LTIME>;
  constexpr std::uint64_t resolution = is_ltime ? 1 : 1'000'000;
  const auto ns = parse_duration_ns(text, is_ltime, resolution, true);
  if (!ns) return {ns.error(), ns.position()};
  const std::uint64_t ticks = ns.value_or(0) / resolution;
  if (ticks > std::numeric_limits<typename T::rep>::max()) return {parse_error::out_of_range, text.find('#') + 1};
  return T::from_ticks(static_cast<typename T::rep>(ticks));
}

constexpr int digit_value(char c) noexcept {
  if (c >= '0' && c <= '9') return c - '0';
  if (c >= 'a' && c <= 'f') return c - 'a' + 10;
  if (c >= 'A' && c <= 'F') return c - 'A' + 10;
  return 99;
}

}  // namespace detail

/**
 * Parses an IEC integer literal into `T` (any of SINT..ULINT, BYTE..LWORD): `42`, `-7`,
 * `1_000`, `2#1010_0101`, `8#17`, `16#FF`, with an optional type prefix naming `T`
 * (`INT#-5`, `WORD#16#FFFF`). A based literal is a bit pattern: `INT#16#FFFF` is -1.
 */
template <AnyInteger T>
[[nodiscard]] constexpr parse_result<T> parse_integer(std::string_view text) noexcept {
  using rep = typename T::rep;
  if (text.empty()) return {parse_error::empty, 0};
  std::size_t i = 0;
  // Optional type prefix: letters then '#'.
  {
    std::size_t j = 0;
    while (j < text.size() && detail::is_letter(text[j])) ++j;
    if (j > 0 && j < text.size() && text[j] == '#') {
      const std::string_view name = text.substr(0, j);
      if (!detail::iequals(name, detail::iec_name<T>::value)) return {parse_error::wrong_prefix, 0};
      i = j + 1;
    } else if (j > 0) {
      return {parse_error::expected_digit, 0};
    }
  }
  if (i >= text.size()) return {parse_error::no_value, i};
  bool negative = false;
  if (text[i] == '-' || text[i] == '+') {
    negative = text[i] == '-';
    ++i;
  }
  // Optional base: digits then '#'.
  unsigned base = 10;
  {
    std::size_t j = i;
    while (j < text.size() && detail::is_digit(text[j])) ++j;
    if (j < text.size() && text[j] == '#') {
      const std::string_view b = text.substr(i, j - i);
      if (b == "2")
        base = 2;
      else if (b == "8")
        base = 8;
      else if (b == "10")
        base = 10;
      else if (b == "16")
        base = 16;
      else
        return {parse_error::invalid_base, i};
      if (negative && base != 10) return {parse_error::invalid_base, i};
      i = j + 1;
    }
  }
  const bool based = base != 10;
  if (i >= text.size()) return {parse_error::no_value, i};
  std::uint64_t magnitude = 0;
  bool overflow = false;
  bool last_was_digit = false;
  const std::size_t digits_at = i;
  for (; i < text.size(); ++i) {
    const char c = text[i];
    if (c == '_') {
      if (!last_was_digit || i + 1 >= text.size() || detail::digit_value(text[i + 1]) >= static_cast<int>(base)) {
        return {parse_error::misplaced_underscore, i};
      }
      last_was_digit = false;
      continue;
    }
    const int d = detail::digit_value(c);
    if (d == 99) {
      if (i == digits_at) return {parse_error::expected_digit, i};
      return {parse_error::trailing_characters, i};
    }
    if (d >= static_cast<int>(base)) return {parse_error::invalid_digit, i};
    if (!overflow && !detail::mul_add(magnitude, base, static_cast<std::uint64_t>(d), magnitude)) overflow = true;
    last_was_digit = true;
  }
  if (overflow) return {parse_error::out_of_range, digits_at};
  if (based) {
    // A bit pattern: must fit the type's width; reinterpreted as the type.
    constexpr unsigned bits = sizeof(rep) * 8;
    if (bits < 64 && magnitude >> (bits % 64) != 0) return {parse_error::out_of_range, digits_at};
    return T(static_cast<rep>(static_cast<std::make_unsigned_t<rep>>(magnitude)));
  }
  if (negative) {
    if constexpr (std::is_unsigned_v<rep>) {
      if (magnitude != 0) return {parse_error::negative, digits_at - 1};
      return T();
    } else {
      const std::uint64_t limit = static_cast<std::uint64_t>(std::numeric_limits<rep>::max()) + 1;
      if (magnitude > limit) return {parse_error::out_of_range, digits_at};
      return T(static_cast<rep>(std::uint64_t{0} - magnitude));  // modular: exact in range
    }
  }
  if (magnitude > static_cast<std::uint64_t>(std::numeric_limits<rep>::max()))
    return {parse_error::out_of_range, digits_at};
  return T(static_cast<rep>(magnitude));
}

/// Parses an IEC BOOL literal: `TRUE`, `FALSE` (any case), `1`, `0`, optionally `BOOL#...`.
[[nodiscard]] constexpr parse_result<BOOL> parse_bool(std::string_view text) noexcept {
  if (text.empty()) return {parse_error::empty, 0};
  std::size_t offset = 0;
  const detail::prefixed p = detail::split_prefix(text);
  if (!p.prefix.empty()) {
    if (!detail::iequals(p.prefix, "BOOL")) return {parse_error::wrong_prefix, 0};
    text = p.body;
    offset = p.body_offset;
    if (text.empty()) return {parse_error::no_value, offset};
  }
  if (detail::iequals(text, "TRUE") || text == "1") return TRUE;
  if (detail::iequals(text, "FALSE") || text == "0") return FALSE;
  return {parse_error::expected_digit, offset};
}

/// Parses an IEC REAL or LREAL literal: `1.5`, `-2.0E-3`, `1_000.5`, `REAL#1.5`. Not
/// constexpr (it uses std::from_chars).
template <AnyReal T>
[[nodiscard]] parse_result<T> parse_real(std::string_view text) noexcept {
  using rep = typename T::rep;
  if (text.empty()) return {parse_error::empty, 0};
  std::size_t offset = 0;
  const detail::prefixed p = detail::split_prefix(text);
  if (!p.prefix.empty()) {
    if (!detail::iequals(p.prefix, detail::iec_name<T>::value)) return {parse_error::wrong_prefix, 0};
    text = p.body;
    offset = p.body_offset;
  }
  if (text.empty()) return {parse_error::no_value, offset};
  // Copy without underscores (which must stand between digits) into a bounded buffer.
  char buffer[128];
  std::size_t n = 0;
  for (std::size_t i = 0; i < text.size(); ++i) {
    const char c = text[i];
    if (c == '_') {
      if (i == 0 || i + 1 >= text.size() || !detail::is_digit(text[i - 1]) || !detail::is_digit(text[i + 1])) {
        return {parse_error::misplaced_underscore, offset + i};
      }
      continue;
    }
    if (!(detail::is_digit(c) || c == '.' || c == '-' || c == '+' || c == 'e' || c == 'E')) {
      return {i == 0 ? parse_error::expected_digit : parse_error::trailing_characters, offset + i};
    }
    if (n == sizeof(buffer)) return {parse_error::out_of_range, offset + i};
    buffer[n++] = c;
  }
  const char* first = buffer;
  if (n > 0 && buffer[0] == '+') ++first;  // from_chars rejects a leading '+'
  // ... but takes a '-' after it: "+-1.5" is no number.
  if (first != buffer && first < buffer + n && (*first == '-' || *first == '+'))
    return {parse_error::expected_digit, offset + 1};
  rep value{};
  const auto [end, ec] = std::from_chars(first, buffer + n, value, std::chars_format::general);
  if (ec == std::errc::result_out_of_range) return {parse_error::out_of_range, offset};
  if (ec != std::errc{} || end == first) return {parse_error::expected_digit, offset};
  if (end != buffer + n) return {parse_error::trailing_characters, offset + static_cast<std::size_t>(end - buffer)};
  return T(value);
}

// ---------------------------------------------------------------------------------------
// Formatting: to_text(out, value) writes the IEC text of `value` to `out` (which must have
// room for max_text_length<T> characters) and returns the end. No terminating NUL.

namespace detail {
constexpr std::size_t decimal_digits(std::uint64_t v) noexcept {
  std::size_t n = 1;
  for (; v >= 10; v /= 10) ++n;
  return n;
}
/// The longest text write_duration writes for durations up to `max_ns`, by construction: each
/// unit with the most digits it can have — the first unit's count of the largest value, any
/// other unit's count below its limit (T#11d23h59m59s999ms is longer than TIME's largest
/// value, T#49d17h2m47s295ms).
constexpr std::size_t longest_duration_text(std::uint64_t max_ns, std::size_t smallest_unit) noexcept {
  std::size_t n = 0;
  for (std::size_t u = 0; u <= smallest_unit; ++u) {
    std::uint64_t largest = max_ns / duration_units[u].ns;
    if (duration_units[u].limit != 0 && largest >= duration_units[u].limit) largest = duration_units[u].limit - 1;
    n += decimal_digits(largest) + duration_units[u].name.size();
  }
  return n;
}
}  // namespace detail

/// The longest text to_text() writes for a T.
template <class T>
inline constexpr std::size_t max_text_length = 0;
template <AnyInteger T>
inline constexpr std::size_t max_text_length<T> = std::numeric_limits<typename T::rep>::digits10 + 2;
template <>
inline constexpr std::size_t max_text_length<BOOL> = 5;  // FALSE
template <>                                              // 19: T#11d23h59m59s999ms
inline constexpr std::size_t max_text_length<TIME> =
    2 + detail::longest_duration_text(std::uint64_t{std::numeric_limits<std::uint32_t>::max()} * 1'000'000, 4);
template <>  // 37: LTIME#213503d23h34m33s709ms551us615ns
inline constexpr std::size_t max_text_length<LTIME> =
    6 + detail::longest_duration_text(std::numeric_limits<std::uint64_t>::max(), 6);
template <>
inline constexpr std::size_t max_text_length<REAL> = 24;
template <>
inline constexpr std::size_t max_text_length<LREAL> = 32;

namespace detail {
constexpr char* write(char* out, std::string_view s) noexcept {
  for (const char c : s) *out++ = c;
  return out;
}
// In the value's own width: on a 32-bit microcontroller an INT or DINT then needs no 64-bit
// division (libgcc's __aeabi_uldivmod).
template <std::unsigned_integral U>
constexpr char* write_unsigned(char* out, U v) noexcept {
  char digits[std::numeric_limits<U>::digits10 + 1];
  std::size_t n = 0;
  do {
    U q;
    if constexpr (sizeof(U) > 4) {
      q = static_cast<U>(divide_by<10>(v));  // no 64-bit division routine on a 32-bit core
    } else {
      q = static_cast<U>(v / 10U);
    }
    digits[n++] = static_cast<char>('0' + (v - q * 10U));
    v = q;
  } while (v != 0);
  while (n > 0) *out++ = digits[--n];
  return out;
}
constexpr char* write_duration(char* out, std::uint64_t ns, std::size_t smallest_unit) noexcept {
  bool any = false;
  for (std::size_t u = 0; u <= smallest_unit; ++u) {
    // (no 64-bit division routine on a 32-bit core: detail/constant_division.hpp)
    const std::uint64_t count = divide_u64(ns, duration_units[u].ns);
    ns -= count * duration_units[u].ns;
    if (count != 0) {
      out = write_unsigned(out, count);
      out = write(out, duration_units[u].name);
      any = true;
    }
  }
  if (!any) {
    out = write(out, "0");
    out = write(out, duration_units[smallest_unit].name);
  }
  return out;
}
}  // namespace detail

/// Decimal text: `-32768`, `255`.
template <AnyInteger T>
constexpr char* to_text(char* out, T value) noexcept {
  using U = std::make_unsigned_t<typename T::rep>;
  const auto v = value.value();
  if constexpr (std::is_signed_v<typename T::rep>) {
    if (v < 0) {
      *out++ = '-';
      return detail::write_unsigned(out, static_cast<U>(U{0} - static_cast<U>(v)));  // the magnitude, -32768 too
    }
  }
  return detail::write_unsigned(out, static_cast<U>(v));
}
/// `TRUE` or `FALSE`.
constexpr char* to_text(char* out, BOOL value) noexcept { return detail::write(out, value ? "TRUE" : "FALSE"); }
/// `T#1h2m3s4ms`; zero is `T#0ms`.
constexpr char* to_text(char* out, TIME value) noexcept {
  return detail::write_duration(detail::write(out, "T#"), std::uint64_t{value.count()} * 1'000'000, 4);
}
/// `LTIME#1ms500us`; zero is `LTIME#0ns`.
constexpr char* to_text(char* out, LTIME value) noexcept {
  return detail::write_duration(detail::write(out, "LTIME#"), value.count(), 6);
}
/// The shortest text that reads back as the same value (`1.5`, `1e+10`, `-0.1`); not constexpr.
template <AnyReal T>
char* to_text(char* out, T value) noexcept {
  const auto result = std::to_chars(out, out + max_text_length<T>, value.value());
  return result.ptr;
}

}  // namespace iecoop

#include <iecoop/detail/pop_macros.hpp>
