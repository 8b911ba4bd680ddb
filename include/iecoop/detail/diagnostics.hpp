// SPDX-License-Identifier: MIT
// iecoop/detail/diagnostics.hpp — helpers that turn misuse into readable compile errors.
// IWYU pragma: private, include <iecoop/iecoop.hpp>
#pragma once

#include <cstddef>
#include <utility>

#include <iecoop/detail/meta.hpp>
#include <iecoop/fault.hpp>

namespace iecoop::detail {

/// Not constexpr: reaching a call to it during constant evaluation (in a consteval
/// function, for instance) stops compilation, and compilers print the call's line, so the
/// message passed here is what the user reads. Write it as "iecoop: <rule>; <fix>".
///
/// It is defined only because Clang 14 fails to evaluate consteval constructors in
/// namespace-scope and default member initializers at compile time and calls them at run
/// time instead: there the check becomes a fault (fault_kind::invalid_value).
inline void compile_error(const char* message) { fault(fault_kind::invalid_value, message); }

/// A name or a literal spelled out as a type, `spelled<'I', 'M'>`, so that a diagnostic shows
/// the user's own text in its template arguments on both compilers (Clang 14 prints a string
/// template argument as a list of numbers, but characters as characters).
template <char... C>
struct spelled {};

template <auto Text, std::size_t... I>
auto spell(std::index_sequence<I...>) -> spelled<Text.chars[I]...>;

/// The characters of `Text` — a constant with `chars` and `size` members, such as a
/// fixed_string or a constant_text — as a spelled<> type.
template <auto Text>
using spelled_t = decltype(spell<Text>(std::make_index_sequence<Text.size>{}));

/// Text computed while compiling, as a structural type (a template argument): what a
/// diagnostic proposes instead of the user's text.
template <std::size_t N>
struct constant_text {
  char chars[N]{};
  std::size_t size = 0;
};

}  // namespace iecoop::detail
