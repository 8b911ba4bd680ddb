// SPDX-License-Identifier: MIT
// iecoop/types.hpp — the IEC 61131-3 elementary types BOOL, SINT..LINT, USINT..ULINT,
// BYTE..LWORD, REAL and LREAL, with PLC semantics in C++.
//
// * Every variable starts at 0 / FALSE, as on a PLC.
// * Integer arithmetic wraps around (two's complement) and is never undefined behaviour;
//   division and MOD by zero go to the fault path (see <iecoop/fault.hpp>) and yield 0.
// * Conversions follow IEC's implicit-conversion rules: widening (INT -> DINT, USINT -> INT,
//   BYTE -> WORD, INT -> REAL) is implicit; narrowing or a change of signedness needs an
//   explicit conversion (DINT_TO_INT, static_cast<INT>(d)), which keeps the low bytes.
// * A C++ integer constant converts implicitly if it fits the type; whether it fits is
//   checked at compile time (INT x = 70000; does not compile).
#pragma once

#include <compare>
#include <concepts>
#include <cstdint>
#include <limits>
#include <type_traits>
#include <utility>

#include <iecoop/config.hpp>
#include <iecoop/detail/diagnostics.hpp>
#include <iecoop/detail/scalar_access.hpp>
#include <iecoop/fault.hpp>

#include <iecoop/detail/push_macros.hpp>

namespace iecoop {

// ---------------------------------------------------------------------------------------
// BOOL

/**
 * IEC BOOL: TRUE or FALSE, one byte, FALSE by default.
 *
 * Constructible from `bool` only (`BOOL b = 1;` does not compile, as in ST). Converts to
 * `bool` in conditions (`if (b)`, `!b`, `b && c`). `&`, `|`, `^` are ST's AND, OR and XOR,
 * which evaluate both operands; `&&` and `||` are ST's AND_THEN and OR_ELSE.
 */
class BOOL {
 public:
  constexpr BOOL() noexcept = default;
  template <std::same_as<bool> B>
  constexpr BOOL(B value) noexcept : value_(value) {}  // NOLINT: implicit like ST's assignment

  /// `b = x > 3;` stores the bool as it is (the same as `b = BOOL(x > 3)`, but a plain
  /// store of the member: see detail/scalar_access.hpp).
  template <std::same_as<bool> B>
  constexpr BOOL& operator=(B value) noexcept {
    value_ = value;
    return *this;
  }

  explicit constexpr operator bool() const noexcept { return value_; }

  // The operands are references: a BOOL passed by value is, for GCC 12, a byte copied as
  // `unsigned char`, which may alias anything and so keeps a loop's variables in memory.
  friend constexpr bool operator==(const BOOL& a, const BOOL& b) noexcept { return a.value_ == b.value_; }
  friend constexpr std::strong_ordering operator<=>(const BOOL& a, const BOOL& b) noexcept { return a.value_ <=> b.value_; }
  friend constexpr BOOL operator!(const BOOL& a) noexcept { return BOOL(!a.value_); }
  friend constexpr BOOL operator&(const BOOL& a, const BOOL& b) noexcept { return BOOL(a.value_ && b.value_); }
  friend constexpr BOOL operator|(const BOOL& a, const BOOL& b) noexcept { return BOOL(a.value_ || b.value_); }
  friend constexpr BOOL operator^(const BOOL& a, const BOOL& b) noexcept { return BOOL(a.value_ != b.value_); }
  constexpr BOOL& operator&=(BOOL b) noexcept { return *this = *this & b; }
  constexpr BOOL& operator|=(BOOL b) noexcept { return *this = *this | b; }
  constexpr BOOL& operator^=(BOOL b) noexcept { return *this = *this ^ b; }

 private:
  friend struct detail::scalar_access;
  bool value_ = false;
};

template <>
struct detail::is_scalar_wrapper<BOOL> : std::true_type {};

inline constexpr BOOL TRUE{true};
inline constexpr BOOL FALSE{false};

// ---------------------------------------------------------------------------------------
// Integers and bit strings

/// The three families of IEC integer types. Arithmetic is allowed on all three (as in
/// CODESYS); implicit conversions only stay within a family, plus unsigned -> signed.
enum class integer_kind : unsigned char {
  signed_int,    ///< SINT, INT, DINT, LINT
  unsigned_int,  ///< USINT, UINT, UDINT, ULINT
  bit_string,    ///< BYTE, WORD, DWORD, LWORD
};

template <class Rep, integer_kind Kind>
class integer;

namespace detail {

template <class T>
inline constexpr bool is_char_v = std::is_same_v<T, char> || std::is_same_v<T, wchar_t> ||
                                  std::is_same_v<T, char8_t> || std::is_same_v<T, char16_t> ||
                                  std::is_same_v<T, char32_t>;

/// A built-in C++ integer type (not bool, not a character type).
template <class T>
concept cpp_integer = std::integral<T> && !std::is_same_v<T, bool> && !is_char_v<T>;

/// Every value of From is a value of To.
template <class From, class To>
inline constexpr bool range_within =
    std::cmp_greater_equal(std::numeric_limits<From>::min(), std::numeric_limits<To>::min()) &&
    std::cmp_less_equal(std::numeric_limits<From>::max(), std::numeric_limits<To>::max());

/// IEC's implicit widening between integer types.
template <class FromRep, integer_kind FromKind, class ToRep, integer_kind ToKind>
inline constexpr bool implicit_widening =
    range_within<FromRep, ToRep> &&
    (FromKind == ToKind || (FromKind == integer_kind::unsigned_int && ToKind == integer_kind::signed_int));

/// The unsigned type wrap-around arithmetic on Rep is done in (at least unsigned int, so
/// that integer promotion can never bring back signed overflow).
template <class Rep>
using wrap_t = std::make_unsigned_t<decltype(+Rep{})>;

template <class T>
struct is_integer : std::false_type {};
template <class Rep, integer_kind Kind>
struct is_integer<integer<Rep, Kind>> : std::true_type {};

}  // namespace detail

/**
 * An IEC integer or bit-string type over the C++ integer `Rep`. Use the aliases: SINT, INT,
 * DINT, LINT, USINT, UINT, UDINT, ULINT, BYTE, WORD, DWORD, LWORD.
 *
 * Same size and alignment as `Rep`, trivially copyable, 0 by default. All arithmetic
 * wraps modulo 2^bits. `/` and `%` (ST's MOD) truncate toward zero; by zero they report
 * fault_kind::division_by_zero and yield 0. `x.value()` gives the C++ integer.
 *
 *     INT i = 32767;
 *     i = i + 1;            // -32768, as on a PLC
 *     DINT d = i;           // implicit widening
 *     i = DINT_TO_INT(d);   // narrowing is explicit (or static_cast<INT>(d))
 */
template <class Rep, integer_kind Kind>
class integer {
  static_assert(detail::cpp_integer<Rep>, "iecoop: integer<Rep, Kind> needs a built-in integer Rep");
  static_assert(std::is_signed_v<Rep> == (Kind == integer_kind::signed_int),
                "iecoop: signed IEC integers need a signed Rep, unsigned ones and bit strings an unsigned Rep");

  using wrap = detail::wrap_t<Rep>;
  static constexpr Rep from_wrap(wrap v) noexcept { return static_cast<Rep>(v); }  // modular
  static constexpr wrap to_wrap(Rep v) noexcept { return static_cast<wrap>(v); }    // modular

 public:
  using rep = Rep;
  static constexpr integer_kind kind = Kind;

  constexpr integer() noexcept = default;

  /// From a C++ integer whose every value fits: implicit, at run time too.
  template <detail::cpp_integer T>
    requires detail::range_within<T, Rep>
  constexpr integer(T value) noexcept : value_(static_cast<Rep>(value)) {}  // NOLINT

  /// From a C++ integer constant of a wider type (`INT x = 5;`): checked at compile time.
  /// A run-time value of a wider C++ type needs an explicit IEC conversion instead, e.g.
  /// DINT_TO_INT(n).
  template <detail::cpp_integer T>
    requires(!detail::range_within<T, Rep>)
  consteval integer(T constant) : value_(static_cast<Rep>(constant)) {  // NOLINT
    if (!std::in_range<Rep>(constant)) {
      detail::compile_error("iecoop: integer constant out of range for this IEC type; use a wider type or an explicit conversion");
    }
  }

  /// From another IEC integer type: implicit where IEC widens implicitly, explicit
  /// otherwise (keeps the low bytes, like DINT_TO_INT).
  template <class R, integer_kind K>
    requires(!std::is_same_v<integer<R, K>, integer>)
  constexpr explicit(!detail::implicit_widening<R, K, Rep, Kind>) integer(integer<R, K> other) noexcept
      : value_(static_cast<Rep>(other.value())) {}

  /// The value as its C++ integer type.
  [[nodiscard]] constexpr Rep value() const noexcept { return value_; }

  /// Explicit conversion to any C++ arithmetic type (but not bool: an INT is no condition).
  template <class T>
    requires(std::is_arithmetic_v<T> && !std::is_same_v<T, bool>)
  explicit constexpr operator T() const noexcept {
    return static_cast<T>(value_);
  }

  // Arithmetic, wrapping modulo 2^bits.
  friend constexpr integer operator+(integer a, integer b) noexcept { return from_wrap(to_wrap(a.value_) + to_wrap(b.value_)); }
  friend constexpr integer operator-(integer a, integer b) noexcept { return from_wrap(to_wrap(a.value_) - to_wrap(b.value_)); }
  friend constexpr integer operator*(integer a, integer b) noexcept { return from_wrap(to_wrap(a.value_) * to_wrap(b.value_)); }
  friend constexpr integer operator/(integer a, integer b) {
    if (b.value_ == 0) return divide_by_zero();
    if constexpr (std::is_signed_v<Rep>) {
      if (b.value_ == -1) return -a;  // the one quotient that overflows wraps instead
    }
    return static_cast<Rep>(a.value_ / b.value_);
  }
  friend constexpr integer operator%(integer a, integer b) {
    if (b.value_ == 0) return divide_by_zero();
    if constexpr (std::is_signed_v<Rep>) {
      if (b.value_ == -1) return integer();
    }
    return static_cast<Rep>(a.value_ % b.value_);
  }
  friend constexpr integer operator-(integer a) noexcept { return from_wrap(wrap{0} - to_wrap(a.value_)); }
  friend constexpr integer operator+(integer a) noexcept { return a; }

  // Bitwise: ST's AND, OR, XOR, NOT on bit strings (and, as CODESYS allows, integers).
  friend constexpr integer operator&(integer a, integer b) noexcept { return static_cast<Rep>(a.value_ & b.value_); }
  friend constexpr integer operator|(integer a, integer b) noexcept { return static_cast<Rep>(a.value_ | b.value_); }
  friend constexpr integer operator^(integer a, integer b) noexcept { return static_cast<Rep>(a.value_ ^ b.value_); }
  friend constexpr integer operator~(integer a) noexcept { return from_wrap(static_cast<wrap>(~to_wrap(a.value_))); }

  constexpr integer& operator+=(integer b) noexcept { return *this = *this + b; }
  constexpr integer& operator-=(integer b) noexcept { return *this = *this - b; }
  constexpr integer& operator*=(integer b) noexcept { return *this = *this * b; }
  constexpr integer& operator/=(integer b) { return *this = *this / b; }
  constexpr integer& operator%=(integer b) { return *this = *this % b; }
  constexpr integer& operator&=(integer b) noexcept { return *this = *this & b; }
  constexpr integer& operator|=(integer b) noexcept { return *this = *this | b; }
  constexpr integer& operator^=(integer b) noexcept { return *this = *this ^ b; }
  constexpr integer& operator++() noexcept { return *this += integer(Rep{1}); }
  constexpr integer& operator--() noexcept { return *this -= integer(Rep{1}); }
  constexpr integer operator++(int) noexcept {
    const integer old = *this;
    ++*this;
    return old;
  }
  constexpr integer operator--(int) noexcept {
    const integer old = *this;
    --*this;
    return old;
  }

  // Comparison with the same type (and, through implicit widening, with narrower types).
  friend constexpr bool operator==(integer a, integer b) noexcept { return a.value_ == b.value_; }
  friend constexpr std::strong_ordering operator<=>(integer a, integer b) noexcept { return a.value_ <=> b.value_; }

  // Comparison with any C++ integer compares the mathematical values (no conversion, so
  // INT(-1) < 4000000000u is true). Where both fit a common type without changing a value,
  // that is a single machine comparison.
  template <detail::cpp_integer T>
  friend constexpr bool operator==(integer a, T b) noexcept {
    return std::cmp_equal(a.value_, b);
  }
  template <detail::cpp_integer T>
  friend constexpr std::strong_ordering operator<=>(integer a, T b) noexcept {
    if constexpr (std::is_signed_v<Rep> == std::is_signed_v<T>) {
      using common = std::common_type_t<Rep, T>;
      return static_cast<common>(a.value_) <=> static_cast<common>(b);
    } else if constexpr (sizeof(Rep) < sizeof(long long) && sizeof(T) < sizeof(long long)) {
      return static_cast<long long>(a.value_) <=> static_cast<long long>(b);
    } else {
      if (std::cmp_less(a.value_, b)) return std::strong_ordering::less;
      if (std::cmp_greater(a.value_, b)) return std::strong_ordering::greater;
      return std::strong_ordering::equal;
    }
  }

 private:
  static integer divide_by_zero() {
    fault(fault_kind::division_by_zero, "integer division or MOD by zero; the result is 0");
    return integer();
  }

  friend struct detail::scalar_access;
  Rep value_ = 0;
};

template <class Rep, integer_kind Kind>
struct detail::is_scalar_wrapper<integer<Rep, Kind>> : std::true_type {};

namespace detail {
/// Two IEC integer types neither of which widens implicitly to the other (INT and UINT,
/// WORD and UINT, ...): IEC needs an explicit conversion before they meet.
template <class A, class B>
concept unrelated_integers = is_integer<A>::value && is_integer<B>::value && !std::is_same_v<A, B> &&
                             !implicit_widening<typename A::rep, A::kind, typename B::rep, B::kind> &&
                             !implicit_widening<typename B::rep, B::kind, typename A::rep, A::kind>;

template <class A, class B>
constexpr bool no_common_type() {
  static_assert(dependent_false<A, B>,
                "iecoop: these IEC integer types have no implicit common type (signed and unsigned, or bit string and "
                "integer); convert one operand explicitly first, e.g. UINT_TO_DINT(u) or static_cast<INT>(w)");
  return false;
}
}  // namespace detail

// Arithmetic, bitwise operations and comparisons between unrelated integer types: rejected
// with a message instead of an unhelpful "no match for operator".
template <class A, class B> requires detail::unrelated_integers<A, B>
void operator+(A, B) { detail::no_common_type<A, B>(); }
template <class A, class B> requires detail::unrelated_integers<A, B>
void operator-(A, B) { detail::no_common_type<A, B>(); }
template <class A, class B> requires detail::unrelated_integers<A, B>
void operator*(A, B) { detail::no_common_type<A, B>(); }
template <class A, class B> requires detail::unrelated_integers<A, B>
void operator/(A, B) { detail::no_common_type<A, B>(); }
template <class A, class B> requires detail::unrelated_integers<A, B>
void operator%(A, B) { detail::no_common_type<A, B>(); }
template <class A, class B> requires detail::unrelated_integers<A, B>
void operator&(A, B) { detail::no_common_type<A, B>(); }
template <class A, class B> requires detail::unrelated_integers<A, B>
void operator|(A, B) { detail::no_common_type<A, B>(); }
template <class A, class B> requires detail::unrelated_integers<A, B>
void operator^(A, B) { detail::no_common_type<A, B>(); }
template <class A, class B> requires detail::unrelated_integers<A, B>
bool operator==(A, B) { return detail::no_common_type<A, B>(); }
template <class A, class B> requires detail::unrelated_integers<A, B>
std::strong_ordering operator<=>(A, B) { return detail::no_common_type<A, B>() ? std::strong_ordering::equal : std::strong_ordering::less; }

using SINT = integer<std::int8_t, integer_kind::signed_int>;
using INT = integer<std::int16_t, integer_kind::signed_int>;
using DINT = integer<std::int32_t, integer_kind::signed_int>;
using LINT = integer<std::int64_t, integer_kind::signed_int>;
using USINT = integer<std::uint8_t, integer_kind::unsigned_int>;
using UINT = integer<std::uint16_t, integer_kind::unsigned_int>;
using UDINT = integer<std::uint32_t, integer_kind::unsigned_int>;
using ULINT = integer<std::uint64_t, integer_kind::unsigned_int>;
using BYTE = integer<std::uint8_t, integer_kind::bit_string>;
using WORD = integer<std::uint16_t, integer_kind::bit_string>;
using DWORD = integer<std::uint32_t, integer_kind::bit_string>;
using LWORD = integer<std::uint64_t, integer_kind::bit_string>;

// ---------------------------------------------------------------------------------------
// REAL and LREAL

template <std::floating_point Rep>
class real;

namespace detail {
template <class T>
struct is_real : std::false_type {};
template <class Rep>
struct is_real<real<Rep>> : std::true_type {};
}  // namespace detail

/**
 * IEC REAL (`real<float>`) and LREAL (`real<double>`): IEEE 754, 0.0 by default.
 *
 * Behaves as the C++ floating type it wraps (it converts to it implicitly, so `r * 2.0f`,
 * `std::sqrt(r)` and comparisons work) and adds what C++'s float lacks for PLC code:
 * zero-initialisation, a distinct type for formatting, and IEC's conversion rules:
 * REAL -> LREAL and small integers (INT -> REAL, DINT -> LREAL) are implicit, LREAL -> REAL
 * needs LREAL_TO_REAL.
 */
template <std::floating_point Rep>
class real {
 public:
  using rep = Rep;

  constexpr real() noexcept = default;
  /// From C++ numbers (`REAL r = 1.5;`, `LREAL x = n;`).
  template <class T>
    requires(std::is_arithmetic_v<T> && !std::is_same_v<T, bool>)
  constexpr real(T value) noexcept : value_(static_cast<Rep>(value)) {}  // NOLINT
  /// From a narrower floating type: REAL -> LREAL is implicit; LREAL -> REAL explicit.
  template <class R>
    requires(!std::is_same_v<R, Rep>)
  constexpr explicit(sizeof(R) > sizeof(Rep)) real(real<R> other) noexcept : value_(static_cast<Rep>(other.value())) {}
  /// From IEC integers the type represents exactly (INT -> REAL, DINT -> LREAL).
  template <class R, integer_kind K>
    requires(K != integer_kind::bit_string && std::numeric_limits<R>::digits <= std::numeric_limits<Rep>::digits)
  constexpr real(integer<R, K> value) noexcept : value_(static_cast<Rep>(value.value())) {}  // NOLINT

  constexpr operator Rep() const noexcept { return value_; }  // NOLINT: behaves as its float
  [[nodiscard]] constexpr Rep value() const noexcept { return value_; }

  constexpr real& operator+=(Rep b) noexcept { value_ += b; return *this; }
  constexpr real& operator-=(Rep b) noexcept { value_ -= b; return *this; }
  constexpr real& operator*=(Rep b) noexcept { value_ *= b; return *this; }
  constexpr real& operator/=(Rep b) noexcept { value_ /= b; return *this; }

 private:
  friend struct detail::scalar_access;
  Rep value_ = 0;
};

template <class Rep>
struct detail::is_scalar_wrapper<real<Rep>> : std::true_type {};

using REAL = real<float>;
using LREAL = real<double>;

// ---------------------------------------------------------------------------------------
// The IEC generic types (ANY_INT, ANY_BIT, ...) as concepts.

/// SINT..LINT, USINT..ULINT (IEC ANY_INT).
template <class T>
concept AnyInt = detail::is_integer<T>::value && T::kind != integer_kind::bit_string;
/// BOOL, BYTE, WORD, DWORD, LWORD (IEC ANY_BIT).
template <class T>
concept AnyBit = std::is_same_v<T, BOOL> || (detail::is_integer<T>::value && T::kind == integer_kind::bit_string);
/// REAL, LREAL (IEC ANY_REAL).
template <class T>
concept AnyReal = detail::is_real<T>::value;
/// Any IEC integer or bit-string type (what iecoop::integer<> models).
template <class T>
concept AnyInteger = detail::is_integer<T>::value;
/// ANY_INT or ANY_REAL (IEC ANY_NUM).
template <class T>
concept AnyNum = AnyInt<T> || AnyReal<T>;

}  // namespace iecoop

// numeric_limits, so generic code sees the IEC types as the integers they are.
template <class Rep, iecoop::integer_kind Kind>
struct std::numeric_limits<iecoop::integer<Rep, Kind>> : public std::numeric_limits<Rep> {
 public:
  static constexpr iecoop::integer<Rep, Kind> min() noexcept { return std::numeric_limits<Rep>::min(); }
  static constexpr iecoop::integer<Rep, Kind> max() noexcept { return std::numeric_limits<Rep>::max(); }
  static constexpr iecoop::integer<Rep, Kind> lowest() noexcept { return std::numeric_limits<Rep>::lowest(); }
  static constexpr bool is_modulo = true;  // IEC arithmetic wraps, whatever the sign
};

#include <iecoop/detail/pop_macros.hpp>
