// SPDX-License-Identifier: MIT
// iecoop/detail/type_name.hpp — a type's name as the compiler spells it, read at compile time
// from __PRETTY_FUNCTION__ (no RTTI), and texts joined at compile time: what names a type in a
// fault message ("GVL_Plant: ...").
// IWYU pragma: private, include <iecoop/iecoop.hpp>
#pragma once

#include <array>
#include <cstddef>
#include <string_view>

#include <iecoop/config.hpp>

#include <iecoop/detail/push_macros.hpp>

namespace iecoop::detail {

template <class T>
constexpr std::string_view type_signature() noexcept {
#if defined(__GNUC__) || defined(__clang__)
  return __PRETTY_FUNCTION__;
#else
#error "iecoop: type names need GCC or Clang (__PRETTY_FUNCTION__)"
#endif
}

/// The compiler's spelling of the template argument `parameter` (`"T = "`) in a function's
/// signature: cut out of "... [with T = <it>; ...]" (GCC) or "... [T = <it>]" (Clang).
constexpr std::string_view argument_spelling(std::string_view signature, std::string_view parameter) noexcept {
  const std::size_t start = signature.find(parameter) + parameter.size();
  const std::size_t semicolon = signature.find(';', start);
  const std::size_t end = semicolon != std::string_view::npos ? semicolon : signature.rfind(']');
  return signature.substr(start, end - start);
}

/// The compiler's spelling of T.
template <class T>
constexpr std::string_view type_name() noexcept {
  return argument_spelling(type_signature<T>(), "T = ");
}

/// The name of the type T without its namespaces and enclosing classes (`E_State`, `IO_PRG`;
/// a template's arguments keep theirs).
template <class T>
constexpr std::string_view short_type_name() noexcept {
  constexpr std::string_view name = type_name<T>();
  const std::size_t angle = name.find('<');
  const std::size_t colons = name.substr(0, angle).rfind("::");
  return colons == std::string_view::npos ? name : name.substr(colons + 2);
}

/// short_type_name<T>() as a string ending in '\0', for a C interface (fault_info).
template <class T>
inline constexpr auto short_type_name_c = [] {
  constexpr std::string_view name = short_type_name<T>();
  std::array<char, name.size() + 1> text{};
  for (std::size_t i = 0; i < name.size(); ++i) text[i] = name[i];
  return text;
}();

/// The texts `Parts` joined, ending in '\0': a message that names a type, for a C interface
/// (fault_info), made while compiling.
template <const std::string_view&... Parts>
inline constexpr auto joined_text = [] {
  std::array<char, (Parts.size() + ... + 1)> text{};
  std::size_t i = 0;
  const auto append = [&](std::string_view part) {
    for (const char c : part) text[i++] = c;
  };
  (append(Parts), ...);
  return text;
}();

}  // namespace iecoop::detail

#include <iecoop/detail/pop_macros.hpp>
