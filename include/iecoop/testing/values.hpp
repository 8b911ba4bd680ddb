// SPDX-License-Identifier: MIT
// iecoop/testing/values.hpp — IEC values in failed checks, as ST writes them: with the kit
// included, `CHECK(wParts == 8)` that fails prints `CHECK( 16#0007 == 8 )`, not `{?}`.
//
//   BOOL TRUE / FALSE          TIME T#1s500ms, LTIME LTIME#...    REAL 1.5
//   INT, DINT, ... 42          BYTE 16#0F, WORD 16#00FF, ...      dates D#2026-11-26, ...
//   STRING 'abc' ($' $$ $N)   WSTRING "abc"                      enumerations by name (enum_components;
//                                                                 else their value)
//   ARRAY [1, 2, 3], as ST writes its initial value: a multi-dimensional one row by row (ARRAY[1..2,
//   1..2] OF INT: [1, 2, 3, 4]), an ARRAY OF ARRAY nested ([[1, 2], [3, 4]]), STRUCT elements as
//   ST's structure literal ([(x := 1, y := 2.5)]); `CHECK(aiResult == aiExpected)` that fails
//   prints `CHECK( [1, 2, 3] == [1, 2, 4] )`.
//
// The variables' wrappers (var<>, outputs, VAR_IN_OUT, RETAIN, PERSISTENT, located variables,
// PROPERTYs) print their value. <iecoop/ostream.hpp> prints the same but for STRING (no quotes)
// and bit strings (decimal), as a program's own output would.
// IWYU pragma: private, include <iecoop/testing.hpp>
#pragma once

#include <cstddef>
#include <cstdint>
#include <sstream>
#include <string>
#include <type_traits>
#include <utility>

#include <doctest/doctest.h>

#include <iecoop/detail/reflect.hpp>
#include <iecoop/detail/utf8.hpp>
#include <iecoop/io/located.hpp>
#include <iecoop/ostream.hpp>
#include <iecoop/pou/variables.hpp>
#include <iecoop/runtime/retain.hpp>
#include <iecoop/sfc/step.hpp>
#include <iecoop/types/array.hpp>
#include <iecoop/types/detail/value_operators.hpp>
#include <iecoop/types/elementary.hpp>
#include <iecoop/types/enumeration.hpp>
#include <iecoop/types/string.hpp>

#include <iecoop/detail/push_macros.hpp>

namespace iecoop::testing {

/// A bit string in hexadecimal with all its digits, as CODESYS shows one: 16#00FF.
template <class Rep>
std::string st_text(integer<Rep, integer_kind::bit_string> value) {
  constexpr int digits = static_cast<int>(sizeof(Rep) * 2);
  std::string text = "16#";
  const auto bits = static_cast<std::uint64_t>(value.value());
  for (int d = digits - 1; d >= 0; --d) text += "0123456789ABCDEF"[(bits >> (4 * d)) & 0xFU];
  return text;
}

/// ST's STRING literal: 'it$'s' (quote `'`, dollar, line feed, tab, ... as $ sequences).
template <class C, std::size_t N>
std::string st_text(const iec_string<C, N>& value) {
  constexpr bool wide = !std::is_same_v<C, char>;
  const char quote = wide ? '"' : '\'';
  std::string text(1, quote);
  for (const C c : value.view()) {
    if (c == static_cast<C>(quote)) {
      text += '$';
      text += quote;
    } else if (c == '$') {
      text += "$$";
    } else if (c == '\n') {
      text += "$N";
    } else if (c == '\r') {
      text += "$R";
    } else if (c == '\t') {
      text += "$T";
    } else if constexpr (wide) {
      char utf8[iecoop::detail::utf8_max_per_unit];
      const char* end = iecoop::detail::put_utf8(utf8, c);
      text.append(utf8, static_cast<std::size_t>(end - utf8));
    } else {
      text += c;
    }
  }
  text += quote;
  return text;
}

/// Any other value: as <iecoop/ostream.hpp> prints it.
template <class T>
std::string st_text(const T& value) {
  std::ostringstream out;
  using iecoop::operator<<;  // also for an enumeration in the user's namespace
  out << value;
  return out.str();
}

template <array_check Check, class T, auto... Bounds>
std::string st_text(const basic_array<Check, T, Bounds...>& value);

namespace detail {
namespace printing {
using iecoop::operator<<;  // also for an enumeration in the user's namespace
template <class T>
concept printable = requires(std::ostream& os, const T& value) { os << value; };
}  // namespace printing

/// An ARRAY's element: as st_text prints it; a STRUCT (an aggregate that the ARRAY's `=`
/// compares, with no operator<<) as ST's structure literal `(x := 1, y := 2.5)`.
template <class T>
std::string element_text(const T& value) {
  if constexpr (requires { typename T::iecoop_array; } || printing::printable<T>) {
    return st_text(value);
  } else if constexpr (Reflectable<T> && iecoop::detail::comparable_element<T>) {
    std::string text = "(";
    [&]<std::size_t... I>(std::index_sequence<I...>) {
      apply_fields(value, [&](const auto&... fields) {
        ((text += (I == 0 ? "" : ", "), text += field_name<T, I>, text += " := ", text += element_text(fields)), ...);
      });
    }(std::make_index_sequence<field_count<T>>{});
    text += ")";
    return text;
  } else {
    return "{?}";
  }
}
}  // namespace detail

/// An ARRAY as ST writes its initial value: [1, 2, 3]; row by row when it has more than one
/// dimension, nested for an ARRAY OF ARRAY.
template <array_check Check, class T, auto... Bounds>
std::string st_text(const basic_array<Check, T, Bounds...>& value) {
  std::string text = "[";
  for (const T& element : value) {
    if (&element != value.begin()) text += ", ";
    text += detail::element_text(element);
  }
  text += "]";
  return text;
}

namespace detail {
template <class T>
doctest::String st_string(const T& value) {
  const std::string text = st_text(value);
  return doctest::String(text.data(), static_cast<doctest::String::size_type>(text.size()));
}
}  // namespace detail

}  // namespace iecoop::testing

namespace doctest {

template <class Rep>
struct StringMaker<iecoop::integer<Rep, iecoop::integer_kind::bit_string>> {
  static String convert(iecoop::integer<Rep, iecoop::integer_kind::bit_string> value) {
    return iecoop::testing::detail::st_string(value);
  }
};
// An enumeration in the user's namespace, where ADL does not find iecoop's operator<<.
template <iecoop::Enumeration E>
struct StringMaker<E> {
  static String convert(E value) { return iecoop::testing::detail::st_string(value); }
};
#if DOCTEST_VERSION_MAJOR == 2 && DOCTEST_VERSION_MINOR == 4
// doctest 2.4 prints an enumeration as its underlying integer without asking StringMaker
// (toString's overload for is_enum types): an IEC enumeration is not one of those for it, so
// that `CHECK(eState == E_State::Run)` prints `Idle == Run`.
namespace detail::types {
template <iecoop::Enumeration E>
struct is_enum<E> {
  static constexpr bool value = false;
};
}  // namespace detail::types
#endif
template <iecoop::array_check Check, class T, auto... Bounds>
struct StringMaker<iecoop::basic_array<Check, T, Bounds...>> {
  static String convert(const iecoop::basic_array<Check, T, Bounds...>& value) {
    return iecoop::testing::detail::st_string(value);
  }
};
template <class C, std::size_t N>
struct StringMaker<iecoop::iec_string<C, N>> {
  static String convert(const iecoop::iec_string<C, N>& value) { return iecoop::testing::detail::st_string(value); }
};
// The wrappers: their value, printed as above.
template <class T, class Owner>
struct StringMaker<iecoop::local<T, Owner>> {
  static String convert(const iecoop::local<T, Owner>& v) { return StringMaker<T>::convert(v.get()); }
};
template <>
struct StringMaker<iecoop::sfc::step_name_view> {
  static String convert(const iecoop::sfc::step_name_view& v) {
    return StringMaker<iecoop::STRING<>>::convert(v.get());
  }
};
template <class T, class Owner>
struct StringMaker<iecoop::read_only<T, Owner>> {
  static String convert(const iecoop::read_only<T, Owner>& v) { return StringMaker<T>::convert(v.get()); }
};
template <class T>
struct StringMaker<iecoop::output<T>> {
  static String convert(const iecoop::output<T>& v) { return StringMaker<T>::convert(v.get()); }
};
template <class T>
struct StringMaker<iecoop::in_out<T>> {
  static String convert(const iecoop::in_out<T>& v) {
    if (!v.bound()) return "<unbound VAR_IN_OUT>";
    return StringMaker<std::remove_const_t<T>>::convert(v.get());
  }
};
template <class T>
struct StringMaker<iecoop::retain<T>> {
  static String convert(const iecoop::retain<T>& v) { return StringMaker<T>::convert(v.get()); }
};
template <class T>
struct StringMaker<iecoop::persistent<T>> {
  static String convert(const iecoop::persistent<T>& v) { return StringMaker<T>::convert(v.get()); }
};
template <class T, iecoop::detail::fixed_string Address, class Image>
struct StringMaker<iecoop::located<T, Address, Image>> {
  static String convert(const iecoop::located<T, Address, Image>& v) { return StringMaker<T>::convert(v.get()); }
};

}  // namespace doctest

#include <iecoop/detail/pop_macros.hpp>
