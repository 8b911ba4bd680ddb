// SPDX-License-Identifier: MIT
// iecoop/fmt.hpp — fmt support: fmt::format("{}", x) prints IEC values as ST writes them:
// TIME as T#1s500ms, LTIME as LTIME#1ms500us, DATE as D#2026-11-23, DT as DT#2026-11-23-12:30:00
// (and TOD, LDATE, LTOD, LDT likewise), BOOL as TRUE/FALSE, STRING and WSTRING as their text
// (WSTRING in UTF-8), an enumeration's component as its name where its components are
// declared (else its value). Integers and REALs accept fmt's number specs ("{:04x}").
// A block's var<>, in_out<> and output<>, and a property, print as their values.
//
// Optional: include it where you format, and link fmt (fmt::fmt or fmt::fmt-header-only).
// The rest of iecoop never needs fmt.
#pragma once

#include <cstddef>
#include <string_view>

#include <fmt/format.h>

#include <iecoop/detail/utf8.hpp>
#include <iecoop/types/date_time.hpp>
#include <iecoop/types/date_time_text.hpp>
#include <iecoop/types/detail/value_operators.hpp>
#include <iecoop/types/elementary.hpp>
#include <iecoop/types/enumeration.hpp>
#include <iecoop/types/literal_text.hpp>
#include <iecoop/types/string.hpp>
#include <iecoop/types/time.hpp>

#include <iecoop/detail/push_macros.hpp>

template <class Rep, iecoop::integer_kind Kind>
struct fmt::formatter<iecoop::integer<Rep, Kind>> : fmt::formatter<Rep> {
  template <class Context>
  auto format(iecoop::integer<Rep, Kind> value, Context& ctx) const {
    return fmt::formatter<Rep>::format(value.value(), ctx);
  }
};

/// An intermediate result formats as its register's value (`i + 1` for INT 32767: 32768).
template <class T>
struct fmt::formatter<iecoop::intermediate<T>> : fmt::formatter<typename iecoop::intermediate<T>::rep> {
  template <class Context>
  auto format(iecoop::intermediate<T> value, Context& ctx) const {
    return fmt::formatter<typename iecoop::intermediate<T>::rep>::format(value.value(), ctx);
  }
};

template <class Rep>
struct fmt::formatter<iecoop::real<Rep>> : fmt::formatter<Rep> {
  template <class Context>
  auto format(iecoop::real<Rep> value, Context& ctx) const {
    return fmt::formatter<Rep>::format(value.value(), ctx);
  }
};

template <>
struct fmt::formatter<iecoop::BOOL> : fmt::formatter<std::string_view> {
  template <class Context>
  auto format(iecoop::BOOL value, Context& ctx) const {
    return fmt::formatter<std::string_view>::format(value ? "TRUE" : "FALSE", ctx);
  }
};

/// An enumeration: its component's name (`Run`) where its components are declared and the
/// value is one, else its value (`12`).
template <iecoop::Enumeration E>
struct fmt::formatter<E, char> : fmt::formatter<std::string_view> {
  template <class Context>
  auto format(E value, Context& ctx) const {
    char text[iecoop::max_text_length<E>];
    const char* end = iecoop::to_text(text, value);
    return fmt::formatter<std::string_view>::format(std::string_view(text, static_cast<std::size_t>(end - text)), ctx);
  }
};

template <class Rep, class Period>
struct fmt::formatter<iecoop::basic_time<Rep, Period>> : fmt::formatter<std::string_view> {
  template <class Context>
  auto format(iecoop::basic_time<Rep, Period> value, Context& ctx) const {
    char text[iecoop::max_text_length<iecoop::basic_time<Rep, Period>>];
    const char* end = iecoop::to_text(text, value);
    return fmt::formatter<std::string_view>::format(std::string_view(text, static_cast<std::size_t>(end - text)), ctx);
  }
};

template <class Rep, class Period, iecoop::time_point_kind Kind>
struct fmt::formatter<iecoop::basic_time_point<Rep, Period, Kind>> : fmt::formatter<std::string_view> {
  template <class Context>
  auto format(iecoop::basic_time_point<Rep, Period, Kind> value, Context& ctx) const {
    char text[iecoop::max_text_length<iecoop::basic_time_point<Rep, Period, Kind>>];
    const char* end = iecoop::to_text(text, value);
    return fmt::formatter<std::string_view>::format(std::string_view(text, static_cast<std::size_t>(end - text)), ctx);
  }
};

template <std::size_t N>
struct fmt::formatter<iecoop::iec_string<char, N>> : fmt::formatter<std::string_view> {
  template <class Context>
  auto format(const iecoop::iec_string<char, N>& value, Context& ctx) const {
    return fmt::formatter<std::string_view>::format(value.view(), ctx);
  }
};

template <std::size_t N>
struct fmt::formatter<iecoop::iec_string<char16_t, N>> : fmt::formatter<std::string_view> {
  template <class Context>
  auto format(const iecoop::iec_string<char16_t, N>& value, Context& ctx) const {
    char text[iecoop::detail::utf8_max_per_unit * N];
    char* end = text;
    for (const char16_t c : value.view()) end = iecoop::detail::put_utf8(end, c);
    return fmt::formatter<std::string_view>::format(std::string_view(text, static_cast<std::size_t>(end - text)), ctx);
  }
};

// var<>, read_only<>, in_out<>, output<>, retain<>, located<> and property<> format as their values (a property calls
// Get).
template <class W>
  requires iecoop::detail::value_wrapper<W>
struct fmt::formatter<W, char> : fmt::formatter<iecoop::detail::unwrapped_t<W>, char> {
  template <class Context>
  auto format(const W& wrapper, Context& ctx) const {
    return fmt::formatter<iecoop::detail::unwrapped_t<W>, char>::format(wrapper.get(), ctx);
  }
};

#include <iecoop/detail/pop_macros.hpp>
