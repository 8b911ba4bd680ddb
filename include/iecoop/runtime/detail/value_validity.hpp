// SPDX-License-Identifier: MIT
// iecoop/runtime/detail/value_validity.hpp — which byte patterns are values of a type: what a RETAIN or
// PERSISTENT image is checked against before its bytes become variables again
// (<iecoop/runtime/retain_image.hpp>).
// IWYU pragma: private, include <iecoop/runtime/retain.hpp>
//
// Most IEC types take every pattern of their bytes (the integers, the bit strings, REAL, TIME,
// the dates); those that do not:
//   BOOL (and bool)      one byte, 0 or 1: any other byte is no value of C++'s bool
//   STRING(n), WSTRING(n) a terminating NUL among the n + 1 characters (else LEN reads past it)
//   a subrange           a value between its limits
//   an enumeration       with 'strict' and its components declared: one of them
//   ARRAY, STRUCT        every element, every member (a STRUCT iecoop can reflect: an aggregate
//                        of standard layout, which a STRUCT that EXTENDS another is not)
// A class iecoop cannot look into is taken as it is.
#pragma once

#include <cstddef>
#include <cstring>
#include <type_traits>
#include <utility>

#include <iecoop/config.hpp>
#include <iecoop/detail/reflect.hpp>
#include <iecoop/types/detail/type_hash.hpp>
#include <iecoop/types/elementary.hpp>
#include <iecoop/types/enumeration.hpp>
#include <iecoop/types/subrange.hpp>

#include <iecoop/detail/push_macros.hpp>

namespace iecoop::detail {

template <class T>
bool valid_value_bytes(const std::byte* at) noexcept;

template <class T>
bool valid_elements(const std::byte* at, std::size_t count) noexcept {
  for (std::size_t i = 0; i < count; ++i) {
    if (!valid_value_bytes<T>(at + i * sizeof(T))) return false;
  }
  return true;
}

template <class T>
bool valid_members(const std::byte* at) noexcept {
  const T probe{};
  const auto* base = reinterpret_cast<const std::byte*>(&probe);
  return apply_fields(probe, [&](const auto&... fields) {
    return (valid_value_bytes<std::remove_cvref_t<decltype(fields)>>(
                at + (reinterpret_cast<const std::byte*>(&fields) - base)) &&
            ...);
  });
}

/**
 * TRUE if the sizeof(T) bytes at `at` are a value of T (see the table at the top of this
 * header). The bytes need not be aligned for T; nothing is read as a T before it is checked.
 */
template <class T>
bool valid_value_bytes(const std::byte* at) noexcept {
  using U = std::remove_cv_t<T>;
  if constexpr (std::is_same_v<U, bool> || std::is_same_v<U, BOOL>) {
    static_assert(sizeof(U) == 1, "iecoop: BOOL is one byte");
    return std::to_integer<unsigned>(at[0]) <= 1U;
  } else if constexpr (iec_string_traits<U>::value) {
    using C = typename U::char_type;
    static_assert(sizeof(U) == (iec_string_traits<U>::capacity + 1) * sizeof(C),
                  "iecoop: STRING(n) is n + 1 characters");
    for (std::size_t i = 0; i <= iec_string_traits<U>::capacity; ++i) {
      C c{};
      std::memcpy(&c, at + i * sizeof(C), sizeof(C));
      if (c == C{}) return true;
    }
    return false;
  } else if constexpr (requires { typename U::iecoop_subrange; }) {
    using rep = typename U::value_type::rep;
    static_assert(sizeof(U) == sizeof(rep), "iecoop: a subrange is its base type's value");
    rep value{};
    std::memcpy(&value, at, sizeof(rep));
    return U::lower.value() <= value && value <= U::upper.value();
  } else if constexpr (std::is_enum_v<U>) {
    if constexpr (Enumeration<U> && enum_strict<U> && has_components<U>) {
      U value{};
      std::memcpy(&value, at, sizeof(U));
      return component_index(value) >= 0;
    } else {
      return true;  // any value of the base type (CODESYS keeps numbers that name no component)
    }
  } else if constexpr (std::is_array_v<U>) {
    return valid_elements<std::remove_extent_t<U>>(at, std::extent_v<U>);
  } else if constexpr (requires { typename U::iecoop_array; }) {
    static_assert(sizeof(U) == U::element_count * sizeof(typename U::value_type), "iecoop: an ARRAY is its elements");
    return valid_elements<typename U::value_type>(at, U::element_count);
  } else if constexpr (is_std_array<U>::value) {
    static_assert(sizeof(U) == std::tuple_size_v<U> * sizeof(typename U::value_type),
                  "iecoop: a std::array is its elements");
    return valid_elements<typename U::value_type>(at, std::tuple_size_v<U>);
  } else if constexpr (member_wise_struct<U>) {
    return valid_members<U>(at);
  } else {
    return true;  // an integer, REAL, TIME, a date, or a class iecoop cannot look into
  }
}

}  // namespace iecoop::detail

#include <iecoop/detail/pop_macros.hpp>
