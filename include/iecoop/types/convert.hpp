// SPDX-License-Identifier: MIT
// iecoop/types/convert.hpp — the one mechanism behind every IEC type conversion: convert<To>(x).
// <iecoop/standard/conversion_functions.hpp> names it <A>_TO_<B> and TO_<B> for each pair of types.
//
// The rules, by kind of type (CODESYS semantics; see docs/porting-guide.md):
//   integer -> integer   keeps the low bytes (INT_TO_SINT(4223) = 127, DINT_TO_UINT(-1) = 65535)
//   REAL    -> integer   rounds to nearest, halves away from zero (REAL_TO_INT(-1.5) = -2),
//                        then keeps the low bytes; NaN gives 0
//   integer -> REAL      the nearest REAL
//   x       -> BOOL      x <> 0;   BOOL -> x: 0 or 1
//   TIME    -> number    milliseconds (LTIME: nanoseconds); number -> TIME likewise
//   TIME   <-> LTIME     exact widening; LTIME_TO_TIME truncates to whole ms and wraps
//   DATE, DT -> number   seconds since 1970 (TOD: ms since midnight; the L forms: ns), and back
//   DT      -> DATE      the day (DT_TO_DATE); DT -> TOD the time of day (DT_TO_TOD); DATE -> DT
//                        its midnight; DATE <-> LDATE, TOD <-> LTOD, DT <-> LDT as TIME <-> LTIME.
//                        A duration and a point, or a TOD and a date, do not convert
//   x       -> STRING    IEC text: 'TRUE', '-5', '1.5', 'T#1s500ms', 'LTIME#1us', 'D#2026-11-23'
//   STRING  -> x         parses that text (surrounding spaces ignored); text that is not a
//                        valid literal gives 0 / FALSE / T#0ms, as CODESYS does
//   STRING <-> WSTRING   Latin-1 <-> UCS-2; characters above 255 become '?'
//   enumeration -> x     its base type's value (TO_INT(eState)); -> STRING: the value ('10'), or
//                        with {attribute 'to_string'} (enum_to_string) the component's name ('Run')
//
// Every form of a variable converts as its value: a block's var<>, retain<>, a property (read
// through its Get), a located variable, an in-out or REFERENCE, a method's output<> and temp<>,
// a subrange (as its base type), a bit `x.N` (a BOOL); so do an ARRAY's element and a STRUCT's
// member, which are values of their type. An ARRAY, a STRUCT or a block instance as a whole
// does not convert, as in ST.
#pragma once

#include <cstddef>
#include <cstdint>
#include <limits>
#include <string_view>
#include <type_traits>

#include <iecoop/config.hpp>
#include <iecoop/detail/diagnostics.hpp>
#include <iecoop/types/date_time.hpp>
#include <iecoop/types/date_time_text.hpp>
#include <iecoop/types/detail/float_to_int.hpp>
#include <iecoop/types/detail/value_operators.hpp>
#include <iecoop/types/elementary.hpp>
#include <iecoop/types/enumeration.hpp>
#include <iecoop/types/literal_text.hpp>
#include <iecoop/types/string.hpp>
#include <iecoop/types/time.hpp>

#include <iecoop/detail/push_macros.hpp>

namespace iecoop {

/// Any IEC elementary type convert<> handles (IEC ANY_ELEMENTARY, as far as iecoop has it).
template <class T>
concept AnyElementary =
    std::is_same_v<T, BOOL> || AnyInteger<T> || AnyReal<T> || AnyDuration<T> || AnyDate<T> || AnyString<T>;

namespace detail {

/// What a conversion takes, once a variable wrapper is unwrapped (argument_t): an elementary
/// value, an intermediate result, an enumeration, or a C++ number or bool.
template <class T>
concept conversion_value = AnyElementary<T> || Intermediate<T> || std::is_enum_v<T> || std::is_same_v<T, bool> ||
                           std::is_floating_point_v<T> || cpp_integer<T>;

/// A class that declares iecoop_value_wrapper but is no value wrapper: a property only its block
/// reads, which converts (inside its block) to From as before, through its own conversion.
template <class X>
concept opted_out_wrapper = !value_wrapper<X> && requires { typename std::remove_cvref_t<X>::iecoop_value_wrapper; };

/// The IEC type a value (a conversion_value) stands for when it is converted.
template <class T>
constexpr auto as_elementary(const T& x) noexcept {
  if constexpr (AnyElementary<T>) {
    return x;
  } else if constexpr (Intermediate<T>) {
    // An intermediate result converts from its whole register (TO_WORD(w + 1) cuts it).
    using reg = typename T::rep;
    if constexpr (std::is_signed_v<reg>) {
      return integer<reg, integer_kind::signed_int>(x.value());
    } else {
      return integer<reg, integer_kind::unsigned_int>(x.value());
    }
  } else if constexpr (std::is_same_v<T, bool>) {
    return BOOL(x);
  } else if constexpr (std::is_floating_point_v<T>) {
    return LREAL(x);
  } else if constexpr (cpp_integer<T> && std::is_signed_v<T>) {
    return LINT(static_cast<std::int64_t>(x));
  } else if constexpr (cpp_integer<T>) {
    return ULINT(static_cast<std::uint64_t>(x));
  } else {
    // An enumeration (convert has checked that T is a conversion_value) converts as its base
    // type's value.
    static_assert(std::is_enum_v<T>);
    require_enumeration<T>();
    if constexpr (Enumeration<T>) {
      return enum_base_t<T>(x);
    } else {
      return INT();
    }
  }
}

/// Rounds a floating value to To's representation, keeping the low bytes of the result.
/// A REAL (float) rounds in float arithmetic, an LREAL in long double (float_to_int.hpp).
template <class Rep, class F>
constexpr Rep round_to(F x) noexcept {
  if constexpr (std::is_same_v<F, float>) {
    if constexpr (std::is_same_v<Rep, std::uint64_t>) {
      // Values between 2^63 and 2^64 need the unsigned range; a float there is a whole number.
      if (x >= 9223372036854775808.0F && x < 18446744073709551616.0F) return whole_float_magnitude(x);
    }
    return static_cast<Rep>(round_to_int64(x));
  } else {
    const auto v = static_cast<long double>(x);
    if constexpr (std::is_same_v<Rep, std::uint64_t>) {
      // Values between 2^63 and 2^64 need the unsigned range.
      constexpr long double two63 = 9223372036854775808.0L;
      if (v >= two63 && v < 2 * two63) return static_cast<std::uint64_t>(v + 0.5L);
    }
    return static_cast<Rep>(round_to_int64(v));
  }
}

constexpr std::string_view trim(std::string_view s) noexcept {
  while (!s.empty() && (s.front() == ' ' || s.front() == '\t')) s.remove_prefix(1);
  while (!s.empty() && (s.back() == ' ' || s.back() == '\t')) s.remove_suffix(1);
  return s;
}

/// A STRING's text as the value of `To`; 0 / FALSE / T#0ms where it is no valid literal.
template <class To>
constexpr To from_text(std::string_view text) noexcept {
  text = trim(text);
  if constexpr (std::is_same_v<To, BOOL>) {
    return parse_bool(text).value_or(FALSE);
  } else if constexpr (AnyInteger<To>) {
    const auto whole = parse_integer<To>(text);
    if (whole) return whole.value_or(To{});
    // CODESYS accepts a REAL text for integers too ('2.7' -> 3). A number outside To's range
    // is no valid literal of To: 0, like any invalid text (not its low bytes).
    if (whole.error() == parse_error::out_of_range || std::is_constant_evaluated()) return To{};
    const auto real = parse_real<LREAL>(text);
    if (!real) return To{};
    using rep = typename To::rep;
    const long double x = real.value_or(LREAL{}).value();
    const long double lowest = static_cast<long double>(std::numeric_limits<rep>::min()) - 0.5L;
    const long double highest = static_cast<long double>(std::numeric_limits<rep>::max()) + 0.5L;
    if (!(x > lowest && x < highest)) return To{};
    return To(round_to<rep>(x));
  } else if constexpr (AnyReal<To>) {
    if (std::is_constant_evaluated()) return To{};
    return parse_real<To>(text).value_or(To{});
  } else if constexpr (std::is_same_v<To, TIME>) {
    return parse_time(text).value_or(TIME{});
  } else if constexpr (std::is_same_v<To, LTIME>) {
    return parse_ltime(text).value_or(LTIME{});
  } else if constexpr (AnyDate<To>) {
    return parse_time_point<To>(text).value_or(To{});
  }
}

/// Durations and points count ticks; the other types hold a value.
template <class X>
constexpr auto ticks_or_value(const X& x) noexcept {
  if constexpr (AnyDuration<X> || AnyDate<X>) {
    return x.count();
  } else {
    return x.value();
  }
}

/// A point in time as another of a kind it converts to (see the rules at the top).
template <class To, class X>
constexpr To convert_point(const X& x) noexcept {
  // Through nanoseconds: exact for every value of a 32-bit point; an L form's own value.
  const std::uint64_t ns = long_point_t<X>(x).count();
  std::uint64_t result = ns;
  if constexpr (X::kind == time_point_kind::date_and_time && To::kind == time_point_kind::date) {
    result = ns - ns % ns_per_day;  // DT_TO_DATE: the day's midnight
  } else if constexpr (X::kind == time_point_kind::date_and_time && To::kind == time_point_kind::time_of_day) {
    result = ns % ns_per_day;  // DT_TO_TOD: the time since midnight
  }
  return static_cast<To>(long_point_t<To>::from_ticks(result));
}

/// Which points in time convert into which: a kind into itself, a DT into a DATE or TOD, a
/// DATE into a DT. (CODESYS's conversions between a TOD and a date have no documented meaning.)
template <class From, class To>
inline constexpr bool points_convert =
    From::kind == To::kind || From::kind == time_point_kind::date_and_time ||
    (From::kind == time_point_kind::date && To::kind == time_point_kind::date_and_time);

template <class From, class To>
constexpr void no_point_conversion() {
  static_assert(dependent_false<From, To>,
                "iecoop: no IEC conversion between the types spelled in `From` and `To`: a duration and a point in "
                "time, or a TIME_OF_DAY and a date, do not convert into each other; compute a point with "
                "DT + TIME, or split a DT with DT_TO_DATE and DT_TO_TOD");
}

/// STRING -> WSTRING and back, character by character.
template <class ToChar, class FromChar>
constexpr ToChar convert_char(FromChar c) noexcept {
  if constexpr (sizeof(ToChar) >= sizeof(FromChar)) {
    return static_cast<ToChar>(static_cast<std::make_unsigned_t<FromChar>>(c));
  } else {
    const auto u = static_cast<std::uint32_t>(c);
    return static_cast<ToChar>(u <= 0xFF ? u : std::uint32_t{'?'});
  }
}

}  // namespace detail

template <class To, class From>
[[nodiscard]] constexpr To convert(From&& from) noexcept(!detail::value_wrapper<From>);

namespace detail {

/// convert<To> of a value that is no wrapper (checked by convert).
template <class To, class From>
constexpr To convert_value(const From& from) noexcept {
  if constexpr (AnyString<To> && Enumeration<From> && enum_to_string<From>) {
    // {attribute 'to_string'}: a component's name; a value that is no component as its number.
    detail::require_components<From>();
    const std::string_view name = component_name(from);
    if (!name.empty()) {
      using C = typename To::char_type;
      C buffer[To::capacity() + 1]{};
      std::size_t n = 0;
      for (const char c : name) {
        if (n == To::capacity()) break;
        buffer[n++] = static_cast<C>(c);
      }
      return To(std::basic_string_view<C>(buffer, n));
    }
  }
  const auto x = detail::as_elementary(from);
  using X = std::remove_cv_t<decltype(x)>;

  if constexpr (std::is_same_v<To, X>) {
    return x;
  } else if constexpr ((AnyDate<To> && AnyDuration<X>) || (AnyDuration<To> && AnyDate<X>)) {
    detail::no_point_conversion<detail::spelled_iec_name_t<X>, detail::spelled_iec_name_t<To>>();
    return To{};
  } else if constexpr (AnyDate<To> && AnyDate<X>) {
    if constexpr (detail::points_convert<X, To>) {
      return detail::convert_point<To>(x);
    } else {
      detail::no_point_conversion<detail::spelled_iec_name_t<X>, detail::spelled_iec_name_t<To>>();
      return To{};
    }
  } else if constexpr (AnyString<To>) {
    using C = typename To::char_type;
    if constexpr (AnyString<X>) {
      C buffer[To::capacity() + 1]{};
      std::size_t n = 0;
      for (auto c : x.view()) {
        if (n == To::capacity()) break;
        buffer[n++] = detail::convert_char<C>(c);
      }
      return To(std::basic_string_view<C>(buffer, n));
    } else {
      char text[max_text_length<X>]{};
      const char* end = to_text(text, x);
      C buffer[max_text_length<X>]{};
      std::size_t n = 0;
      for (const char* p = text; p != end; ++p) buffer[n++] = static_cast<C>(*p);
      return To(std::basic_string_view<C>(buffer, n));
    }
  } else if constexpr (AnyString<X>) {
    if constexpr (std::is_same_v<typename X::char_type, char>) {
      return detail::from_text<To>(x.view());
    } else {
      return detail::from_text<To>(convert<STRING<X::capacity()>>(x).view());
    }
  } else if constexpr (std::is_same_v<To, BOOL>) {
    return BOOL(detail::ticks_or_value(x) != 0);
  } else if constexpr (std::is_same_v<X, BOOL>) {
    if constexpr (AnyDuration<To> || AnyDate<To>) {
      return To::from_ticks(x ? 1 : 0);
    } else {
      return To(static_cast<typename To::rep>(x ? 1 : 0));
    }
  } else if constexpr (AnyInteger<To>) {
    using R = typename To::rep;
    if constexpr (AnyInteger<X>) {
      return To(static_cast<R>(x.value()));
    } else if constexpr (AnyReal<X>) {
      return To(detail::round_to<R>(x.value()));
    } else {  // duration or point in time: its ticks
      return To(static_cast<R>(x.count()));
    }
  } else if constexpr (AnyReal<To>) {
    using R = typename To::rep;
    return To(static_cast<R>(detail::ticks_or_value(x)));
  } else if constexpr (AnyDuration<To> || AnyDate<To>) {
    using R = typename To::rep;
    if constexpr (AnyDuration<X>) {
      return static_cast<To>(x);
    } else if constexpr (AnyReal<X>) {
      return To::from_ticks(detail::round_to<R>(x.value()));
    } else {
      return To::from_ticks(static_cast<R>(x.value()));
    }
  }
}

}  // namespace detail

/**
 * Converts an IEC value to the IEC type `To` with IEC (CODESYS) semantics; the rules are
 * listed at the top of this header. This is what every <A>_TO_<B> and TO_<B> calls. A variable
 * of any form (a block's var<>, a property, a located variable, an in-out, a subrange) converts
 * as its value.
 *
 *     convert<INT>(REAL(2.5))      // 3
 *     convert<STRING<>>(T#1s500ms) // 'T#1s500ms'
 */
template <class To, class From>
[[nodiscard]] constexpr To convert(From&& from) noexcept(!detail::value_wrapper<From>) {
  static_assert(AnyElementary<To>,
                "iecoop: convert<To>: To must be an IEC elementary type (BOOL, INT, REAL, TIME, STRING<N>, ...)");
  if constexpr (detail::opted_out_wrapper<From>) {
    // Here, in the function the user called, so that the compilers show the user's line first.
    static_assert(
        detail::dependent_false<From>,
        "iecoop: this property's Get is for its own block only (owner_only_get), where it is read with .get(): "
        "write TO_LREAL(Gain.get()) inside the block");
    return To{};
  } else if constexpr (!detail::conversion_value<detail::argument_t<From>>) {
    static_assert(
        detail::dependent_false<detail::argument_t<From>>,
        "iecoop: a conversion (TO_<type>, <A>_TO_<B>, convert<T>) takes an elementary value (BOOL, an integer, "
        "REAL, TIME, a date, STRING, an enumeration) or a variable of one, and this argument (its type is in "
        "the brackets) is none; ST converts no ARRAY, STRUCT or block instance either: convert an element or a "
        "member, e.g. TO_LREAL(aValues[i]) or TO_LREAL(stPos.x)");
    return To{};
  } else if constexpr (detail::value_wrapper<From>) {
    return detail::convert_value<To>(detail::argument_value(std::forward<From>(from)));
  } else {
    return detail::convert_value<To>(from);
  }
}

namespace detail {

/// What the named conversion <From>_TO_<To> takes, a wrapper unwrapped: a From, a value that
/// converts to From implicitly (a narrower integer, a literal), or an intermediate result of
/// From or of a type narrower than From (converted from its whole register).
template <class From, class A>
concept conversion_source = std::is_convertible_v<const A&, From> ||
                            (AnyInteger<From> && Intermediate<A> && widens_implicitly<typename A::nominal_type, From>);

/// A C++ array of characters: a string literal, taken by TO_<B>'s literal overload.
template <class X>
concept char_array = std::is_array_v<std::remove_cvref_t<X>> &&
                     is_char_v<std::remove_cv_t<std::remove_extent_t<std::remove_cvref_t<X>>>>;

}  // namespace detail

/// The function object behind a named conversion <From>_TO_<To>: takes a From (or what
/// converts to it implicitly, such as a literal) and returns convert<To>(x).
template <class From, class To>
struct conversion {
  constexpr To operator()(From x) const noexcept { return convert<To>(x); }
  /// An intermediate result of From (or of a type narrower than From) converts from its whole
  /// register, as the conversion of a temporary result does in CODESYS (INT_TO_DINT(i + 1) is
  /// 32768 for i = 32767; WORD_TO_BYTE(w + 1) cuts to 8 bits).
  template <class N>
    requires(AnyInteger<From> && detail::widens_implicitly<N, From>)
  constexpr To operator()(intermediate<N> x) const noexcept {
    return convert<To>(x);
  }
  /// A variable of any form whose value is a From or widens into one (a block's var<>, a
  /// property, a located variable, an in-out, a method's output<> or temp<>, a subrange): its
  /// value, read once (a property through its Get).
  template <class X>
    requires(detail::value_wrapper<X> && detail::conversion_source<From, detail::argument_t<X>>)
  constexpr To operator()(X&& x) const {
    return (*this)(detail::argument_value(std::forward<X>(x)));
  }
  /// Anything else: a value of another IEC type (INT_TO_REAL of a DINT) or no elementary value
  /// (an ARRAY, a STRUCT, a block instance), rejected with what to write instead.
  template <class X>
    requires(!detail::conversion_source<From, detail::argument_t<X>> && !detail::opted_out_wrapper<X>)
  constexpr To operator()(X&&) const noexcept {
    using A = detail::argument_t<X>;
    if constexpr (!detail::conversion_value<A>) {
      static_assert(
          detail::dependent_false<A>,
          "iecoop: a conversion (TO_<type>, <A>_TO_<B>, convert<T>) takes an elementary value (BOOL, an integer, "
          "REAL, TIME, a date, STRING, an enumeration) or a variable of one, and this argument (its type is in "
          "the brackets) is none; ST converts no ARRAY, STRUCT or block instance either: convert an element or a "
          "member, e.g. TO_LREAL(aValues[i]) or TO_LREAL(stPos.x)");
    } else {
      // The argument's IEC name where it has one (a STRING, a C++ number: its type).
      using argument = std::conditional_t<detail::iec_name<detail::nominal_t<A>>::value.empty(), A,
                                          detail::spelled_iec_name_t<detail::nominal_t<A>>>;
      static_assert(detail::dependent_false<argument, detail::spelled_iec_name_t<From>>,
                    "iecoop: <A>_TO_<B> takes an A, or a type that widens into A implicitly, and this argument's type "
                    "(the first in the brackets) is not the conversion's source type (the second); write the "
                    "conversion named after the argument's type (e.g. DINT_TO_REAL for a DINT), or TO_<B>(x)");
    }
    return To{};
  }
};
/// STRING_TO_<To> and WSTRING_TO_<To> take strings of any capacity, literals, and variables of
/// any form that hold such a string.
template <class C, std::size_t N, class To>
struct conversion<iec_string<C, N>, To> {
  template <std::size_t M>
  constexpr To operator()(const iec_string<C, M>& x) const noexcept {
    return convert<To>(x);
  }
  template <std::size_t M>
  constexpr To operator()(const C (&literal)[M]) const noexcept {
    return convert<To>(iec_string<C, M>(literal));
  }
  template <class W>
    requires(detail::value_wrapper<W> && AnyString<detail::argument_t<W>> &&
             std::is_same_v<typename detail::argument_t<W>::char_type, C>)
  constexpr To operator()(W&& x) const {
    return convert<To>(std::forward<W>(x));
  }
};

/// The function object behind the overloaded conversion TO_<To> (IEC 3rd edition): takes any
/// elementary value, and a variable of any form holding one.
template <class To>
struct to_type {
  template <class From>
    requires(!detail::char_array<From>)
  constexpr To operator()(From&& x) const noexcept(!detail::value_wrapper<From>) {
    if constexpr (detail::opted_out_wrapper<From>) {
      static_assert(
          detail::dependent_false<From>,
          "iecoop: this property's Get is for its own block only (owner_only_get), where it is read with .get(): "
          "write TO_LREAL(Gain.get()) inside the block");
      return To{};
    } else if constexpr (!detail::conversion_value<detail::argument_t<From>>) {
      static_assert(
          detail::dependent_false<detail::argument_t<From>>,
          "iecoop: a conversion (TO_<type>, <A>_TO_<B>, convert<T>) takes an elementary value (BOOL, an integer, "
          "REAL, TIME, a date, STRING, an enumeration) or a variable of one, and this argument (its type is in "
          "the brackets) is none; ST converts no ARRAY, STRUCT or block instance either: convert an element or a "
          "member, e.g. TO_LREAL(aValues[i]) or TO_LREAL(stPos.x)");
      return To{};
    } else {
      return convert<To>(detail::argument_value(std::forward<From>(x)));
    }
  }
  template <class C, std::size_t M>
    requires detail::is_char_v<C>
  constexpr To operator()(const C (&literal)[M]) const noexcept {
    return convert<To>(iec_string<C, M>(literal));
  }
};

/// TRUNC(x): REAL/LREAL to DINT, truncating toward zero (CODESYS). Out-of-range values
/// keep the low bytes of the (saturated) 64-bit result; NaN gives 0.
template <AnyReal R>
[[nodiscard]] constexpr DINT TRUNC(R x) noexcept {
  return DINT(static_cast<std::int32_t>(detail::trunc_to_int64(x.value())));
}
/// TRUNC_INT(x): like TRUNC, to INT.
template <AnyReal R>
[[nodiscard]] constexpr INT TRUNC_INT(R x) noexcept {
  return INT(static_cast<std::int16_t>(detail::trunc_to_int64(x.value())));
}

}  // namespace iecoop

#include <iecoop/detail/pop_macros.hpp>
