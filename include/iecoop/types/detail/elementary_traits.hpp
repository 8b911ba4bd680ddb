// SPDX-License-Identifier: MIT
// iecoop/types/detail/elementary_traits.hpp — what the elementary types' headers share: the
// integer kinds, the class templates declared ahead, the traits that recognise them (is_integer,
// is_real, ...), each type's IEC name and the refusal of an implicit conversion.
// IWYU pragma: private, include <iecoop/types/elementary.hpp>
#pragma once

#include <climits>
#include <compare>
#include <concepts>
#include <cstdint>
#include <limits>
#include <string_view>
#include <type_traits>
#include <utility>

#include <iecoop/config.hpp>
#include <iecoop/detail/diagnostics.hpp>
#include <iecoop/detail/iec_value.hpp>
#include <iecoop/detail/scalar_access.hpp>
#include <iecoop/fault.hpp>

#include <iecoop/detail/push_macros.hpp>

namespace iecoop {

/// The three families of IEC integer types. Arithmetic is allowed on all three (as in
/// CODESYS); implicit conversions only stay within a family, plus unsigned -> signed.
enum class integer_kind : unsigned char {
  signed_int,    ///< SINT, INT, DINT, LINT
  unsigned_int,  ///< USINT, UINT, UDINT, ULINT
  bit_string,    ///< BYTE, WORD, DWORD, LWORD
};

template <class Rep, integer_kind Kind>
class integer;
template <class T>
class intermediate;

template <std::floating_point Rep>
class real;

namespace detail {
/// Whether the integer operators take their operands by reference (Clang) or by value (GCC and
/// the others): see integer<>::operand.
#if defined(__clang__)
inline constexpr bool operands_by_reference = true;
#else
inline constexpr bool operands_by_reference = false;
#endif

template <class T>
struct is_integer : std::false_type {};
template <class Rep, integer_kind Kind>
struct is_integer<integer<Rep, Kind>> : std::true_type {};
template <class T>
struct is_intermediate : std::false_type {};
template <class T>
struct is_intermediate<intermediate<T>> : std::true_type {};

template <class T>
struct is_real : std::false_type {};
template <class Rep>
struct is_real<real<Rep>> : std::true_type {};

/// The IEC name of an elementary type ("DINT"), or empty; each type's header names its types.
template <class T>
struct iec_name {
  static constexpr std::string_view value{};
};

template <class T, std::size_t... I>
auto spell_iec_name(std::index_sequence<I...>) -> spelled<iec_name<T>::value[I]...>;
/// The IEC name of T as a spelled<> type, for diagnostics.
template <class T>
using spelled_iec_name_t = decltype(spell_iec_name<T>(std::make_index_sequence<iec_name<T>::value.size()>{}));

/// `From` goes into `To` only through an explicit conversion: the template arguments spell
/// both IEC names, which is the name of the conversion to write.
template <class From, class To>
constexpr void no_implicit_conversion() {
  static_assert(dependent_false<From>,
                "iecoop: ST converts the type spelled in `From` into the one spelled in `To` only explicitly "
                "(a narrowing, signed and unsigned, bit string and integer, REAL and integer, BOOL and number); "
                "write the conversion From_TO_To(x) (e.g. DINT_TO_INT(x)) or TO_To(x)");
}

template <class T>
inline constexpr bool is_char_v = std::is_same_v<T, char> || std::is_same_v<T, wchar_t> || std::is_same_v<T, char8_t> ||
                                  std::is_same_v<T, char16_t> || std::is_same_v<T, char32_t>;

/// A built-in C++ integer type (not bool, not a character type).
template <class T>
concept cpp_integer = std::integral<T> && !std::is_same_v<T, bool> && !is_char_v<T>;

/// The IEC integer type an enumeration stands on (its base type), void for any other type;
/// <iecoop/types/enumeration.hpp> gives it for the IEC enumerations.
template <class E>
struct enum_base_of {
  using type = void;
};
}  // namespace detail

}  // namespace iecoop

#include <iecoop/detail/pop_macros.hpp>
