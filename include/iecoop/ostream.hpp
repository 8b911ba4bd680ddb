// SPDX-License-Identifier: MIT
// iecoop/ostream.hpp — operator<< for IEC values, printing them as ST writes them (TIME as
// T#1s500ms, DATE as D#2026-11-23, BOOL as TRUE/FALSE, WSTRING in UTF-8, an enumeration's
// component by its name, an ARRAY as [1, 2, 3]). Optional: the core never needs <ostream>;
// include this for iostreams, or for readable values in failed test assertions.
#pragma once

#include <cstddef>
#include <ostream>
#include <string_view>

#include <iecoop/detail/utf8.hpp>
#include <iecoop/pou/property.hpp>
#include <iecoop/pou/variables.hpp>
#include <iecoop/types/array.hpp>
#include <iecoop/types/date_time.hpp>
#include <iecoop/types/date_time_text.hpp>
#include <iecoop/types/elementary.hpp>
#include <iecoop/types/enumeration.hpp>
#include <iecoop/types/literal_text.hpp>
#include <iecoop/types/string.hpp>
#include <iecoop/types/subrange.hpp>
#include <iecoop/types/time.hpp>

#include <iecoop/detail/push_macros.hpp>

namespace iecoop {

namespace detail {
template <class T>
std::ostream& print_text(std::ostream& os, T value) {
  char text[max_text_length<T>];
  const char* end = to_text(text, value);
  return os << std::string_view(text, static_cast<std::size_t>(end - text));
}
}  // namespace detail

inline std::ostream& operator<<(std::ostream& os, BOOL value) { return detail::print_text(os, value); }

/// An enumeration prints its component's name (`Run`) where its components are declared
/// (enum_components) and the value is one, else its value (`12`).
template <Enumeration E>
std::ostream& operator<<(std::ostream& os, E value) {
  return detail::print_text(os, value);
}

template <class Rep, integer_kind Kind>
std::ostream& operator<<(std::ostream& os, integer<Rep, Kind> value) {
  return detail::print_text(os, value);
}

/// An intermediate result prints its register's value (`i + 1` for INT 32767: 32768).
template <class T>
std::ostream& operator<<(std::ostream& os, intermediate<T> value) {
  if constexpr (std::is_signed_v<typename intermediate<T>::rep>) {
    return os << static_cast<long long>(value.value());
  } else {
    return os << static_cast<unsigned long long>(value.value());
  }
}

template <class Rep>
std::ostream& operator<<(std::ostream& os, real<Rep> value) {
  return detail::print_text(os, value);
}

template <class Rep, class Period>
std::ostream& operator<<(std::ostream& os, basic_time<Rep, Period> value) {
  return detail::print_text(os, value);
}

template <class Rep, class Period, time_point_kind Kind>
std::ostream& operator<<(std::ostream& os, basic_time_point<Rep, Period, Kind> value) {
  return detail::print_text(os, value);
}

template <std::size_t N>
std::ostream& operator<<(std::ostream& os, const iec_string<char, N>& value) {
  return os << value.view();
}

template <std::size_t N>
std::ostream& operator<<(std::ostream& os, const iec_string<char16_t, N>& value) {
  for (const char16_t c : value.view()) {
    char utf8[detail::utf8_max_per_unit];
    const char* end = detail::put_utf8(utf8, c);
    os.write(utf8, end - utf8);
  }
  return os;
}

/// A subrange prints its value.
template <class Base, auto Lower, auto Upper>
std::ostream& operator<<(std::ostream& os, const subrange<Base, Lower, Upper>& value) {
  return os << value.get();
}

template <class T, class Owner>
std::ostream& operator<<(std::ostream& os, const local<T, Owner>& variable) {
  return os << variable.get();
}
template <class T, class Owner>
std::ostream& operator<<(std::ostream& os, const read_only<T, Owner>& variable) {
  return os << variable.get();
}
template <class T>
std::ostream& operator<<(std::ostream& os, const in_out<T>& variable) {
  if (!variable.bound()) return os << "<unbound VAR_IN_OUT>";
  return os << variable.get();
}
template <class T>
std::ostream& operator<<(std::ostream& os, const output<T>& variable) {
  return os << variable.get();
}

/// A property prints its value (a Get call).
template <Property P>
  requires requires(const P& p) { p.get(); }
std::ostream& operator<<(std::ostream& os, const P& p) {
  return os << p.get();
}

/// An ARRAY prints as ST writes its initial value, `[1, 2, 3]`: row by row when it has more
/// than one dimension, nested for an ARRAY OF ARRAY; its elements as they print.
template <array_check Check, class T, auto... Bounds>
  requires requires(std::ostream& os, const T& element) { os << element; }
std::ostream& operator<<(std::ostream& os, const basic_array<Check, T, Bounds...>& value) {
  os << '[';
  for (const T& element : value) {
    if (&element != value.begin()) os << ", ";
    os << element;
  }
  return os << ']';
}

}  // namespace iecoop

#include <iecoop/detail/pop_macros.hpp>
