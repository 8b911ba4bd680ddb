// SPDX-License-Identifier: MIT
// iecoop/types/literals.hpp — IEC literals written as in ST, checked at compile time:
// "T#1h2m3s4ms"_iec, "LTIME#1ms500us"_iec, "INT#-5"_iec, "WORD#16#FFFF"_iec, "TRUE"_iec,
// "D#2026-11-23"_iec, "TOD#12:30:00.5"_iec, "DT#2026-11-23-12:30:00"_iec.
//
// The literal's prefix picks its type: T#/TIME# give TIME, LT#/LTIME# give LTIME, a type
// name (SINT#..ULINT#, BYTE#..LWORD#, BOOL#) gives that type, D#/DATE#, TOD#/TIME_OF_DAY#,
// DT#/DATE_AND_TIME#, LD#/LDATE#, LTOD#/LTIME_OF_DAY#, LDT#/LDATE_AND_TIME# the points in
// time. An invalid literal does not compile, and the static_assert that stops it says what is
// wrong. For text known only at run time use parse_time(), parse_integer<T>(), parse_dt() and
// friends from <iecoop/types/literal_text.hpp> and <iecoop/types/date_time_text.hpp>.
#pragma once

#include <cstddef>
#include <string_view>
#include <utility>

#include <iecoop/config.hpp>
#include <iecoop/detail/diagnostics.hpp>
#include <iecoop/detail/fixed_string.hpp>
#include <iecoop/types/date_time.hpp>
#include <iecoop/types/date_time_text.hpp>
#include <iecoop/types/elementary.hpp>
#include <iecoop/types/literal_text.hpp>
#include <iecoop/types/time.hpp>

#include <iecoop/detail/push_macros.hpp>

namespace iecoop {

namespace detail {

/// One static_assert per parse error, so the compiler prints the one that applies. constexpr,
/// not consteval, as the two below: Clang 16 leaves a call to a consteval function that a
/// literal in a member function of a class template makes (an undefined reference at link
/// time); the checks are static_asserts, made when the function is instantiated either way.
template <parse_error E>
constexpr void check_literal() noexcept {
  static_assert(E != parse_error::empty, "iecoop: empty IEC literal; write e.g. \"T#1s\"_iec");
  static_assert(E != parse_error::missing_prefix,
                "iecoop: an IEC duration literal needs its prefix; write \"T#15ms\", not \"15ms\"");
  static_assert(E != parse_error::wrong_prefix,
                "iecoop: unknown literal prefix; use T#, TIME#, LT#, LTIME#, D#, TOD#, DT#, LDATE#, LTOD#, LDT#, BOOL# "
                "or an integer type such as INT# or WORD#");
  static_assert(E != parse_error::no_value, "iecoop: nothing follows the '#' of the IEC literal; write e.g. \"T#0ms\"");
  static_assert(E != parse_error::expected_digit,
                "iecoop: the IEC literal has a character where a digit belongs; check the number");
  static_assert(
      E != parse_error::misplaced_underscore,
      "iecoop: '_' may only stand between two digits or between a unit and the next number (\"T#1h_30m\", \"1_000\")");
  static_assert(E != parse_error::missing_unit,
                "iecoop: a number in a duration literal has no unit; add d, h, m, s, ms, us or ns");
  static_assert(E != parse_error::unknown_unit,
                "iecoop: unknown unit in a duration literal; the units are d, h, m, s, ms, us, ns");
  static_assert(E != parse_error::unit_order,
                "iecoop: units of a duration literal must appear once each from highest to lowest (d h m s ms us ns); "
                "write \"T#4d13ms\", not \"T#13ms4d\"");
  static_assert(E != parse_error::unit_overflow, "iecoop: only the highest unit of a duration literal may overflow");
  static_assert(
      E != parse_error::fraction_not_last,
      "iecoop: only the last unit of a duration literal may have a fraction; write \"T#1s500ms\" or \"T#1.5s\"");
  static_assert(
      E != parse_error::too_precise,
      "iecoop: the literal is finer than its type resolves (TIME: 1 ms); use LTIME# for microseconds and nanoseconds");
  static_assert(E != parse_error::out_of_range,
                "iecoop: the literal's value does not fit its type (TIME: up to T#49d17h2m47s295ms); use a wider type "
                "such as LTIME or LINT");
  static_assert(E != parse_error::negative,
                "iecoop: negative value for an unsigned type (TIME and LTIME are unsigned, as in CODESYS)");
  static_assert(E != parse_error::invalid_digit,
                "iecoop: a digit that is not valid in the literal's base (2#: 0-1, 8#: 0-7, 16#: 0-F)");
  static_assert(E != parse_error::invalid_base,
                "iecoop: the base of an integer literal must be 2#, 8#, 10# or 16#, without sign");
  static_assert(E != parse_error::trailing_characters, "iecoop: unexpected characters after the IEC literal");
  static_assert(
      E != parse_error::expected_separator,
      "iecoop: a date literal separates its fields with '-' and the time of day's with ':' (\"D#2026-11-23\", "
      "\"TOD#12:30:00\", \"DT#2026-11-23-12:30:00\")");
  static_assert(E != parse_error::invalid_date,
                "iecoop: no such date: the month is 1..12 and the day within the month (February has 29 days in leap "
                "years only: 2000 is one, 2100 is not)");
  static_assert(E != parse_error::invalid_time_of_day,
                "iecoop: no such time of day: the hour is 0..23, minutes and seconds 0..59 (\"TOD#23:59:59.999\")");
}

/// The checks of a DATE, TOD or DT literal: its own words for a value out of range or too
/// precise, the common ones for the rest.
template <parse_error E>
constexpr void check_point_literal() noexcept {
  static_assert(E != parse_error::out_of_range,
                "iecoop: the date is outside its type's range (DATE and DT: 1970-01-01 to DT#2106-02-07-06:28:15; "
                "LDATE and LDT: 1970-01-01 to LDT#2554-07-21-23:34:33.709551615); use LDATE# or LDT# for later dates");
  static_assert(E != parse_error::too_precise,
                "iecoop: the literal is finer than its type resolves (DT: 1 s, TOD: 1 ms); drop the fraction, or use "
                "LDT# or LTOD# (1 ns)");
  if constexpr (E != parse_error::out_of_range && E != parse_error::too_precise) check_literal<E>();
}

/// `error`, as a value that depends on the template argument X, so a check_literal<> in a
/// discarded `if constexpr` branch is not instantiated.
template <auto X>
consteval parse_error depends_on(parse_error error) noexcept {
  return error;
}

/// The types an IEC literal can have, picked by its prefix.
enum class literal_type {
  time,
  ltime,
  boolean,
  sint,
  int_,
  dint,
  lint,
  usint,
  uint,
  udint,
  ulint,
  byte,
  word,
  dword,
  lword,
  date,
  ldate,
  tod,
  ltod,
  dt,
  ldt,
  untyped,
  unknown
};

template <literal_type L>
struct literal_cxx_type;
template <>
struct literal_cxx_type<literal_type::time> {
  using type = TIME;
};
template <>
struct literal_cxx_type<literal_type::ltime> {
  using type = LTIME;
};
template <>
struct literal_cxx_type<literal_type::boolean> {
  using type = BOOL;
};
template <>
struct literal_cxx_type<literal_type::sint> {
  using type = SINT;
};
template <>
struct literal_cxx_type<literal_type::int_> {
  using type = INT;
};
template <>
struct literal_cxx_type<literal_type::dint> {
  using type = DINT;
};
template <>
struct literal_cxx_type<literal_type::lint> {
  using type = LINT;
};
template <>
struct literal_cxx_type<literal_type::usint> {
  using type = USINT;
};
template <>
struct literal_cxx_type<literal_type::uint> {
  using type = UINT;
};
template <>
struct literal_cxx_type<literal_type::udint> {
  using type = UDINT;
};
template <>
struct literal_cxx_type<literal_type::ulint> {
  using type = ULINT;
};
template <>
struct literal_cxx_type<literal_type::byte> {
  using type = BYTE;
};
template <>
struct literal_cxx_type<literal_type::word> {
  using type = WORD;
};
template <>
struct literal_cxx_type<literal_type::dword> {
  using type = DWORD;
};
template <>
struct literal_cxx_type<literal_type::lword> {
  using type = LWORD;
};
template <>
struct literal_cxx_type<literal_type::date> {
  using type = DATE;
};
template <>
struct literal_cxx_type<literal_type::ldate> {
  using type = LDATE;
};
template <>
struct literal_cxx_type<literal_type::tod> {
  using type = TOD;
};
template <>
struct literal_cxx_type<literal_type::ltod> {
  using type = LTOD;
};
template <>
struct literal_cxx_type<literal_type::dt> {
  using type = DT;
};
template <>
struct literal_cxx_type<literal_type::ldt> {
  using type = LDT;
};

// The parsers below work on a copy of the literal's characters made inside the constant
// evaluation: GCC cannot fold pointer checks on the address of a template argument
// object when the undefined-behaviour sanitizer instruments them.
template <fixed_string S>
struct literal_chars {
  char chars[S.size + 1]{};
  constexpr literal_chars() noexcept {
    for (std::size_t i = 0; i <= S.size; ++i) chars[i] = S.chars[i];
  }
  [[nodiscard]] constexpr std::string_view view() const noexcept { return {chars, S.size}; }
};

/// The integer literal_type whose IEC name is `prefix` (ignoring case): untyped for no prefix,
/// unknown for a name that is no integer type.
template <std::size_t... I>
constexpr literal_type integer_literal_type(std::string_view prefix, std::index_sequence<I...>) noexcept {
  constexpr literal_type integers[] = {literal_type::sint,  literal_type::int_,  literal_type::dint,
                                       literal_type::lint,  literal_type::usint, literal_type::uint,
                                       literal_type::udint, literal_type::ulint, literal_type::byte,
                                       literal_type::word,  literal_type::dword, literal_type::lword};
  literal_type found = prefix.empty() ? literal_type::untyped : literal_type::unknown;
  static_cast<void>((
      (iequals(prefix, iec_name<typename literal_cxx_type<integers[I]>::type>::value) && (found = integers[I], true)) ||
      ...));
  return found;
}

template <fixed_string S>
consteval literal_type classify_literal() noexcept {
  const literal_chars<S> copy;
  const std::string_view text = copy.view();
  const prefixed p = split_prefix(text);
  switch (classify_duration_prefix(p.prefix)) {
    case duration_prefix::time: return literal_type::time;
    case duration_prefix::ltime: return literal_type::ltime;
    case duration_prefix::none: break;
  }
  switch (classify_point_prefix(p.prefix)) {
    case point_prefix::date: return literal_type::date;
    case point_prefix::ldate: return literal_type::ldate;
    case point_prefix::tod: return literal_type::tod;
    case point_prefix::ltod: return literal_type::ltod;
    case point_prefix::dt: return literal_type::dt;
    case point_prefix::ldt: return literal_type::ldt;
    case point_prefix::none: break;
  }
  if (iequals(text, "TRUE") || iequals(text, "FALSE") || iequals(p.prefix, "BOOL")) return literal_type::boolean;
  return integer_literal_type(p.prefix, std::make_index_sequence<12>{});
}

template <class T, fixed_string S>
consteval parse_result<T> parse_literal() noexcept {
  const literal_chars<S> copy;
  if constexpr (std::is_same_v<T, TIME>) {
    return parse_time(copy.view());
  } else if constexpr (std::is_same_v<T, LTIME>) {
    return parse_ltime(copy.view());
  } else if constexpr (std::is_same_v<T, BOOL>) {
    return parse_bool(copy.view());
  } else if constexpr (AnyDate<T>) {
    return parse_time_point<T>(copy.view());
  } else {
    return parse_integer<T>(copy.view());
  }
}

/// The literal `Given` breaks "only the highest unit may overflow"; `Write` spells the same
/// duration written as IEC allows (the template arguments show both).
template <class Given, class Write>
constexpr void duration_unit_overflow() noexcept {
  static_assert(dependent_false<Given>,
                "iecoop: only the highest unit of a duration literal may overflow; write the literal `Write` spells "
                "(the same duration) instead of the one `Given` spells");
}

/// What a duration literal whose lower unit overflows has wrong besides (none, or the error).
template <class T, fixed_string S>
consteval parse_error normalized_duration_error() noexcept {
  const literal_chars<S> copy;
  return normalized_duration<T>(copy.view()).error();
}

/// The valid spelling of a TIME or LTIME literal in which a lower unit overflows ("T#2m75s"
/// is "T#3m15s"), for the diagnostic.
template <class T, fixed_string S>
consteval auto normalized_duration_literal() noexcept {
  const literal_chars<S> copy;
  constant_text<64> text;
  char buffer[64]{};
  const char* end = to_text(buffer, normalized_duration<T>(copy.view()).value_or(T{}));
  for (const char* p = buffer; p != end; ++p) text.chars[text.size++] = *p;
  return text;
}

}  // namespace detail

inline namespace literals {

/**
 * An IEC literal as ST writes it; its prefix picks the type.
 *
 *     using namespace iecoop;            // or: using namespace iecoop::literals;
 *     TIME  pt = "T#1h2m3s4ms"_iec;
 *     LTIME lt = "LTIME#1ms500us"_iec;
 *     WORD  w  = "WORD#16#FFFF"_iec;
 *     DT    dt = "DT#2026-11-23-12:30:00"_iec;
 *     "t#5m68s"_iec;                     // does not compile: only the highest unit may overflow
 */
// constexpr, not consteval: Clang 14 does not evaluate a consteval literal operator template
// used inside a function template, and leaves an undefined reference instead. Every check is
// a static_assert on S, and the value is a constant either way.
template <detail::fixed_string S>
constexpr auto operator""_iec() noexcept {
  constexpr detail::literal_type type = detail::classify_literal<S>();
  if constexpr (type == detail::literal_type::untyped) {
    static_assert(detail::dependent_false<decltype(S)>,
                  "iecoop: an IEC literal needs a type prefix (T#, LTIME#, INT#, WORD#, BOOL#, ...); for an untyped "
                  "number use a C++ literal such as 0xFF");
    return 0;
  } else if constexpr (type == detail::literal_type::unknown) {
    detail::check_literal<detail::depends_on<S>(parse_error::wrong_prefix)>();
    return 0;
  } else {
    using T = typename detail::literal_cxx_type<type>::type;
    constexpr parse_result<T> result = detail::parse_literal<T, S>();
    if constexpr (result.error() == parse_error::unit_overflow) {
      // The same duration spelt validly, unless the literal is wrong besides (then that error).
      constexpr parse_error besides = detail::normalized_duration_error<T, S>();
      if constexpr (besides == parse_error::none) {
        detail::duration_unit_overflow<detail::spelled_t<S>,
                                       detail::spelled_t<detail::normalized_duration_literal<T, S>()>>();
      } else {
        detail::check_literal<besides>();
      }
    } else if constexpr (AnyDate<T>) {
      detail::check_point_literal<result.error()>();
    } else {
      detail::check_literal<result.error()>();
    }
    return result.value_or(T{});
  }
}

}  // namespace literals
}  // namespace iecoop

#include <iecoop/detail/pop_macros.hpp>
