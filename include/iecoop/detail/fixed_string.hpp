// SPDX-License-Identifier: MIT
// iecoop/detail/fixed_string.hpp — a string usable as a template argument (for "..."_iec).
// IWYU pragma: private, include <iecoop/types/literals.hpp>
#pragma once

#include <cstddef>

namespace iecoop::detail {

/// The characters of a string literal, as a structural type (a class template argument).
template <std::size_t N>
struct fixed_string {
  char chars[N]{};
  static constexpr std::size_t size = N - 1;  // without the terminating NUL

  consteval fixed_string(const char (&text)[N]) noexcept {  // NOLINT: made from literals
    for (std::size_t i = 0; i < N; ++i) chars[i] = text[i];
  }
};

}  // namespace iecoop::detail
