// SPDX-License-Identifier: MIT
// iecoop/types/bool.hpp — IEC BOOL: TRUE or FALSE, one byte, FALSE by default; no arithmetic,
// compared only with BOOL (part of <iecoop/types/elementary.hpp>).
#pragma once

#include <iecoop/types/detail/elementary_traits.hpp>

#include <iecoop/detail/push_macros.hpp>

namespace iecoop {

// ---------------------------------------------------------------------------------------
// BOOL

class BOOL;

namespace detail {
/// Two operands of a BOOL operation: BOOL or C++ bool, at least one of them a BOOL.
template <class A, class B>
concept bool_operands =
    occurs_in<A, BOOL, bool> && occurs_in<B, BOOL, bool> && (std::is_same_v<A, BOOL> || std::is_same_v<B, BOOL>);
/// A number a BOOL might meet: a C++ number (which C++ would silently combine with the BOOL's
/// 0 or 1), a REAL or an IEC integer.
template <class T>
concept number_for_bool = (std::is_arithmetic_v<T> && !std::is_same_v<T, bool>) || is_real<T>::value ||
                          is_integer<T>::value || is_intermediate<T>::value;
/// A BOOL meeting a number: C++ would compute with it as 0 or 1; ST does not compile it.
template <class A, class B>
concept bool_with_number =
    (std::is_same_v<A, BOOL> && (number_for_bool<B> || std::is_same_v<B, BOOL> || std::is_same_v<B, bool>)) ||
    (std::is_same_v<B, BOOL> && (number_for_bool<A> || std::is_same_v<A, bool>));
template <class A, class B>
concept bool_compared_with_number =
    (std::is_same_v<A, BOOL> && number_for_bool<B>) || (std::is_same_v<B, BOOL> && number_for_bool<A>);

template <class T>
constexpr bool bool_is_no_number() {
  static_assert(dependent_false<T>,
                "iecoop: BOOL is not a number: ST has no arithmetic on BOOL and compares it only with BOOL; "
                "convert it first (BOOL_TO_INT(b)), or compare with TRUE / FALSE");
  return false;
}
/// The type of a rejected arithmetic between a BOOL and a number: the number's (or BOOL), so
/// that the expression around it raises no second error.
template <class A, class B>
using bool_arithmetic_t = std::conditional_t<std::is_same_v<A, BOOL>, B, A>;
template <class A, class B>
constexpr bool_arithmetic_t<A, B> no_bool_arithmetic() {
  bool_is_no_number<A>();
  return bool_arithmetic_t<A, B>{};
}
}  // namespace detail

/**
 * IEC BOOL: TRUE or FALSE, one byte, FALSE by default.
 *
 * Constructible from `bool` only (`BOOL b = 1;` does not compile, as in ST). A BOOL is a
 * condition wherever C++ expects one (`if (b)`, `bool ok = b;`, `b && c`). `&`, `|`, `^` are
 * ST's AND, OR and XOR, which evaluate both operands; `&&` and `||` are ST's AND_THEN and
 * OR_ELSE; `!` (and `~`, as on the other bit strings) is NOT. Comparisons of IEC values yield
 * BOOL, so `x = 1 OR x = 3` is `x == 1 | x == 3`. Arithmetic with a BOOL, and comparing it
 * with a number, do not compile.
 */
class BOOL {
 public:
  constexpr BOOL() noexcept = default;
  template <std::same_as<bool> B>
  constexpr BOOL(B value) noexcept : value_(value) {}  // implicit: implicit like ST's assignment

  /// `b = x > 3;` stores the bool as it is (the same as `b = BOOL(x > 3)`, but a plain
  /// store of the member: see detail/scalar_access.hpp).
  template <std::same_as<bool> B>
  constexpr BOOL& operator=(B value) noexcept {
    value_ = value;
    return *this;
  }

  /// A condition: `if (b)`, `while (!b)`, `bool ok = b;`.
  constexpr operator bool() const noexcept { return value_; }  // implicit: a BOOL is a condition

  // The operands are references: a BOOL passed by value is, for GCC 12, a byte copied as
  // `unsigned char`, which may alias anything and so keeps a loop's variables in memory.
  // Each operator takes a BOOL or a C++ bool on either side (a template: an exact match, so
  // that C++'s own operators on bool, which would yield int, are never chosen).
  template <class A, class B>
    requires detail::bool_operands<A, B>
  friend constexpr BOOL operator&(const A& a, const B& b) noexcept {
    return BOOL(bit(a) && bit(b));
  }
  template <class A, class B>
    requires detail::bool_operands<A, B>
  friend constexpr BOOL operator|(const A& a, const B& b) noexcept {
    return BOOL(bit(a) || bit(b));
  }
  template <class A, class B>
    requires detail::bool_operands<A, B>
  friend constexpr BOOL operator^(const A& a, const B& b) noexcept {
    return BOOL(bit(a) != bit(b));
  }
  friend constexpr BOOL operator!(const BOOL& a) noexcept { return BOOL(!a.value_); }
  friend constexpr BOOL operator~(const BOOL& a) noexcept { return BOOL(!a.value_); }

  template <class A, class B>
    requires detail::bool_operands<A, B>
  friend constexpr BOOL operator==(const A& a, const B& b) noexcept {
    return BOOL(bit(a) == bit(b));
  }
  template <class A, class B>
    requires detail::bool_operands<A, B>
  friend constexpr BOOL operator!=(const A& a, const B& b) noexcept {
    return BOOL(bit(a) != bit(b));
  }
  template <class A, class B>
    requires detail::bool_operands<A, B>
  friend constexpr BOOL operator<(const A& a, const B& b) noexcept {
    return BOOL(bit(a) < bit(b));
  }
  template <class A, class B>
    requires detail::bool_operands<A, B>
  friend constexpr BOOL operator<=(const A& a, const B& b) noexcept {
    return BOOL(bit(a) <= bit(b));
  }
  template <class A, class B>
    requires detail::bool_operands<A, B>
  friend constexpr BOOL operator>(const A& a, const B& b) noexcept {
    return BOOL(bit(a) > bit(b));
  }
  template <class A, class B>
    requires detail::bool_operands<A, B>
  friend constexpr BOOL operator>=(const A& a, const B& b) noexcept {
    return BOOL(bit(a) >= bit(b));
  }
  friend constexpr std::strong_ordering operator<=>(const BOOL& a, const BOOL& b) noexcept {
    return a.value_ <=> b.value_;
  }

  constexpr BOOL& operator&=(const BOOL& b) noexcept { return *this = *this & b; }
  constexpr BOOL& operator|=(const BOOL& b) noexcept { return *this = *this | b; }
  constexpr BOOL& operator^=(const BOOL& b) noexcept { return *this = *this ^ b; }

  // What C++ would compute with a BOOL as the number 0 or 1 through its conversion to bool
  // (`b + 1`, `b == 1`, `r * b`, `-b`): rejected, with the rule and the fix.
  template <class A, class B>
    requires detail::bool_with_number<A, B>
  friend constexpr detail::bool_arithmetic_t<A, B> operator+(const A&, const B&) {
    return detail::no_bool_arithmetic<A, B>();
  }
  template <class A, class B>
    requires detail::bool_with_number<A, B>
  friend constexpr detail::bool_arithmetic_t<A, B> operator-(const A&, const B&) {
    return detail::no_bool_arithmetic<A, B>();
  }
  template <class A, class B>
    requires detail::bool_with_number<A, B>
  friend constexpr detail::bool_arithmetic_t<A, B> operator*(const A&, const B&) {
    return detail::no_bool_arithmetic<A, B>();
  }
  template <class A, class B>
    requires detail::bool_with_number<A, B>
  friend constexpr detail::bool_arithmetic_t<A, B> operator/(const A&, const B&) {
    return detail::no_bool_arithmetic<A, B>();
  }
  template <class A, class B>
    requires detail::bool_with_number<A, B>
  friend constexpr detail::bool_arithmetic_t<A, B> operator%(const A&, const B&) {
    return detail::no_bool_arithmetic<A, B>();
  }
  template <class A, class B>
    requires detail::bool_with_number<A, B>
  friend constexpr detail::bool_arithmetic_t<A, B> operator<<(const A&, const B&) {
    return detail::no_bool_arithmetic<A, B>();
  }
  template <class A, class B>
    requires detail::bool_with_number<A, B>
  friend constexpr detail::bool_arithmetic_t<A, B> operator>>(const A&, const B&) {
    return detail::no_bool_arithmetic<A, B>();
  }
  template <class A, class B>
    requires detail::bool_compared_with_number<A, B>
  friend constexpr detail::bool_arithmetic_t<A, B> operator&(const A&, const B&) {
    return detail::no_bool_arithmetic<A, B>();
  }
  template <class A, class B>
    requires detail::bool_compared_with_number<A, B>
  friend constexpr detail::bool_arithmetic_t<A, B> operator|(const A&, const B&) {
    return detail::no_bool_arithmetic<A, B>();
  }
  template <class A, class B>
    requires detail::bool_compared_with_number<A, B>
  friend constexpr detail::bool_arithmetic_t<A, B> operator^(const A&, const B&) {
    return detail::no_bool_arithmetic<A, B>();
  }
  template <class A, class B>
    requires detail::bool_compared_with_number<A, B>
  friend bool operator==(const A&, const B&) {
    return detail::bool_is_no_number<A>();
  }
  template <class A, class B>
    requires detail::bool_compared_with_number<A, B>
  friend bool operator!=(const A&, const B&) {
    return detail::bool_is_no_number<A>();
  }
  template <class A, class B>
    requires detail::bool_compared_with_number<A, B>
  friend bool operator<(const A&, const B&) {
    return detail::bool_is_no_number<A>();
  }
  template <class A, class B>
    requires detail::bool_compared_with_number<A, B>
  friend bool operator<=(const A&, const B&) {
    return detail::bool_is_no_number<A>();
  }
  template <class A, class B>
    requires detail::bool_compared_with_number<A, B>
  friend bool operator>(const A&, const B&) {
    return detail::bool_is_no_number<A>();
  }
  template <class A, class B>
    requires detail::bool_compared_with_number<A, B>
  friend bool operator>=(const A&, const B&) {
    return detail::bool_is_no_number<A>();
  }
  template <std::same_as<BOOL> B>
  friend constexpr BOOL operator-(const B&) {
    detail::bool_is_no_number<B>();
    return BOOL{};
  }
  template <std::same_as<BOOL> B>
  friend constexpr BOOL operator+(const B&) {
    detail::bool_is_no_number<B>();
    return BOOL{};
  }

 private:
  static constexpr bool bit(const BOOL& b) noexcept { return b.value_; }
  static constexpr bool bit(bool b) noexcept { return b; }

  friend struct detail::scalar_access;
  bool value_ = false;
};

template <>
struct detail::is_scalar_wrapper<BOOL> : std::true_type {};
template <>
struct detail::is_iec_value<BOOL> : std::true_type {};

template <>
struct detail::iec_name<BOOL> {
  static constexpr std::string_view value = "BOOL";
};

inline constexpr BOOL TRUE{true};
inline constexpr BOOL FALSE{false};

}  // namespace iecoop

#include <iecoop/detail/pop_macros.hpp>
