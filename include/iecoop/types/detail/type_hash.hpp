// SPDX-License-Identifier: MIT
// iecoop/types/detail/type_hash.hpp — a 32-bit FNV-1a hash, and a type's hash computed from its
// name at compile time, without RTTI: what RETAIN and PERSISTENT images record so that a
// retyped variable (INT -> UINT) is recognised.
// IWYU pragma: private, include <iecoop/runtime/retain.hpp>
//
// The IEC elementary types, STRING(n), WSTRING(n) and arrays of them are hashed under their
// IEC names ("INT", "STRING(10)", "ARRAY[3] OF INT"), which every compiler and platform
// spells alike. Any other type is hashed under the compiler's spelling of its name, read from
// __PRETTY_FUNCTION__ as detail/reflect.hpp reads names: "app::ST_Recipe" for a user STRUCT,
// followed, where iecoop can reflect the STRUCT (member_wise_struct), by each member's name and
// type: "app::ST_Recipe{rSpeed:REAL;bOn:BOOL;}", so that retyping a member (USINT -> BOOL)
// changes the hash though the size stays.
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <string_view>
#include <type_traits>
#include <utility>

#include <iecoop/config.hpp>
#include <iecoop/detail/reflect.hpp>
#include <iecoop/detail/type_name.hpp>
#include <iecoop/types/elementary.hpp>
#include <iecoop/types/string.hpp>
#include <iecoop/types/time.hpp>

#include <iecoop/detail/push_macros.hpp>

namespace iecoop::detail {

/// FNV-1a, 32 bits: small, constexpr, and the same on every platform (numbers are fed as
/// their little-endian bytes).
class fnv1a {
 public:
  constexpr fnv1a& add_byte(std::uint8_t byte) noexcept {
    hash_ = (hash_ ^ byte) * 16777619U;
    return *this;
  }
  constexpr fnv1a& add(std::string_view text) noexcept {
    for (const char c : text) add_byte(static_cast<std::uint8_t>(c));
    return *this;
  }
  /// `value` as 8 little-endian bytes.
  constexpr fnv1a& add_number(std::uint64_t value) noexcept {
    for (int i = 0; i < 8; ++i) {
      add_byte(static_cast<std::uint8_t>(value & 0xFFU));
      value >>= 8U;
    }
    return *this;
  }
  /// `value` in decimal digits, as it is spelled in a type name.
  constexpr fnv1a& add_decimal(std::uint64_t value) noexcept {
    char digits[20]{};
    int n = 0;
    do {
      digits[n++] = static_cast<char>('0' + value % 10U);
      value /= 10U;
    } while (value != 0);
    while (n > 0) add_byte(static_cast<std::uint8_t>(digits[--n]));
    return *this;
  }
  [[nodiscard]] constexpr std::uint32_t value() const noexcept { return hash_; }

 private:
  std::uint32_t hash_ = 2166136261U;
};

template <class T>
struct is_std_array : std::false_type {};
template <class T, std::size_t N>
struct is_std_array<std::array<T, N>> : std::true_type {};

template <class T>
struct iec_string_traits {
  static constexpr bool value = false;
};
template <class C, std::size_t N>
struct iec_string_traits<iec_string<C, N>> {
  static constexpr bool value = true;
  static constexpr bool wide = !std::is_same_v<C, char>;
  static constexpr std::size_t capacity = N;
};

/// A STRUCT whose members iecoop reads one by one: an aggregate of standard layout (no base
/// with members of its own next to the derived ones: a STRUCT that EXTENDS another is read
/// as a whole), not a union, default-constructible (its members' offsets are read from a
/// value of it).
template <class T>
concept member_wise_struct = std::is_class_v<T> && std::is_aggregate_v<T> && std::is_standard_layout_v<T> &&
                             std::is_default_constructible_v<T> && Reflectable<T>;

/// Feeds a signed decimal number to `hash`.
constexpr fnv1a& add_signed(fnv1a& hash, std::int64_t value) noexcept {
  if (value < 0) hash.add("-");
  return hash.add_decimal(value < 0 ? 0U - static_cast<std::uint64_t>(value) : static_cast<std::uint64_t>(value));
}

/// Feeds T's name to `hash`: the IEC name where T has one, else the compiler's spelling.
template <class T>
constexpr void add_type_name(fnv1a& hash) noexcept {
  using U = std::remove_cv_t<T>;
  if constexpr (std::is_enum_v<U>) {
    hash.add(type_name<U>());  // an enumeration by its full name: its IEC name leaves out the namespaces
  } else if constexpr (!iec_name<U>::value.empty()) {
    hash.add(iec_name<U>::value);  // BOOL, the integers, REAL, LREAL, TIME, LTIME
  } else if constexpr (iec_string_traits<U>::value) {
    hash.add(iec_string_traits<U>::wide ? "WSTRING(" : "STRING(").add_decimal(iec_string_traits<U>::capacity).add(")");
  } else if constexpr (std::is_array_v<U>) {
    hash.add("ARRAY[").add_decimal(std::extent_v<U>).add("] OF ");
    add_type_name<std::remove_extent_t<U>>(hash);
  } else if constexpr (requires { typename U::iecoop_array; }) {
    hash.add("ARRAY[");  // with the IEC bounds: ARRAY[0..9] is another type than ARRAY[1..10]
    for (std::size_t d = 1; d <= U::rank; ++d) {
      if (d > 1) hash.add(",");
      add_signed(hash, U::lower(d)).add("..");
      add_signed(hash, U::upper(d));
    }
    hash.add("] OF ");
    add_type_name<typename U::value_type>(hash);
  } else if constexpr (is_std_array<U>::value) {
    hash.add("ARRAY[").add_decimal(std::tuple_size_v<U>).add("] OF ");
    add_type_name<typename U::value_type>(hash);
  } else if constexpr (member_wise_struct<U>) {
    hash.add(type_name<U>()).add("{");
    [&]<std::size_t... I>(std::index_sequence<I...>) {
      ((hash.add(field_name<U, I>).add(":"), add_type_name<field_type<U, I>>(hash), hash.add(";")), ...);
    }(std::make_index_sequence<field_count<U>>{});
    hash.add("}");
  } else {
    hash.add(type_name<U>());
  }
}

/// T's 32-bit hash.
template <class T>
inline constexpr std::uint32_t type_hash = [] {
  fnv1a hash;
  add_type_name<T>(hash);
  return hash.value();
}();

}  // namespace iecoop::detail

#include <iecoop/detail/pop_macros.hpp>
