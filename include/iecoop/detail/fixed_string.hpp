// SPDX-License-Identifier: MIT
// iecoop/detail/fixed_string.hpp — iecoop::fixed_string, a string usable as a template
// argument: what "..."_iec literals and direct addresses (located<T, "%IX0.5">,
// address_of<"%QW2">) are made of. Public, for code that passes such text on:
//     template <class T, iecoop::fixed_string Address> using input = located<T, Address>;
// IWYU pragma: private, include <iecoop/iecoop.hpp>
#pragma once

#include <cstddef>

namespace iecoop {

/// The characters of a string literal, as a structural type (a class template argument).
template <std::size_t N>
struct fixed_string {
  char chars[N]{};
  static constexpr std::size_t size = N - 1;  // without the terminating NUL

  consteval fixed_string(const char (&text)[N]) noexcept {  // implicit: made from literals
    for (std::size_t i = 0; i < N; ++i) chars[i] = text[i];
  }
};

namespace detail {
using iecoop::fixed_string;  // iecoop's own headers spell it detail::fixed_string
}  // namespace detail

}  // namespace iecoop
