// SPDX-License-Identifier: MIT
// iecoop/types/elementary.hpp — the IEC 61131-3 elementary types BOOL, SINT..LINT, USINT..ULINT,
// BYTE..LWORD, REAL and LREAL, with PLC semantics in C++.
//
// * Every variable starts at 0 / FALSE, as on a PLC.
// * Integer arithmetic is CODESYS's: an operation computes its result in the registers of
//   the target — at least 32 bits, 64 on a 64-bit target — and the result is cut to the
//   variable's width only when it is assigned (see intermediate<T>). So `wVar1 + 1 = wVar2`
//   is FALSE for wVar1 = 65535, wVar2 = 0, while `wVar3 := wVar1 + 1;` stores 0. Nothing is
//   undefined behaviour: the registers wrap too. Division and MOD by zero go to the fault
//   path (see <iecoop/fault.hpp>) and yield 0.
// * Conversions follow IEC's implicit-conversion rules: widening (INT -> DINT, USINT -> INT,
//   BYTE -> WORD, INT -> REAL) is implicit; narrowing or a change of signedness needs an
//   explicit conversion (DINT_TO_INT, static_cast<INT>(d)), which keeps the low bytes.
// * A C++ integer constant converts implicitly if it fits the type; whether it fits is
//   checked at compile time (INT x = 70000; does not compile).
// * A comparison yields a BOOL, as in ST, so `b := x = 1 OR x = 3;` is `b = x == 1 | x == 3;`.
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

// ---------------------------------------------------------------------------------------
// Integers and bit strings

/// The width in bits of the registers integer expressions are computed in (see
/// intermediate<T>): CODESYS computes at least in 32 bits, and in 64 bits on 64-bit targets.
/// Define IECOOP_REGISTER_BITS as 32 or 64 (the same in every translation unit) to compute as
/// another target does — 32 to test on a PC what a Cortex-M or x86 PLC computes.
#if defined(IECOOP_REGISTER_BITS)
inline constexpr int register_bits = IECOOP_REGISTER_BITS;
#else
inline constexpr int register_bits = sizeof(void*) * CHAR_BIT >= 64 ? 64 : 32;
#endif
static_assert(register_bits == 32 || register_bits == 64, "iecoop: IECOOP_REGISTER_BITS is 32 or 64");

namespace detail {

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

/// An IEC integer value: a variable's type, or an intermediate result.
template <class X>
concept int_value = is_integer<X>::value || is_intermediate<X>::value;

/// The IEC type an integer value has: its own, or the one of the expression it results from.
template <class X>
struct nominal_of {
  using type = X;
};
template <class T>
struct nominal_of<intermediate<T>> {
  using type = T;
};
template <class X>
using nominal_t = typename nominal_of<X>::type;

/// An IEC integer type From converts to To implicitly (the same type, or IEC widening).
template <class From, class To>
inline constexpr bool widens_implicitly = false;
template <class FR, integer_kind FK, class TR, integer_kind TK>
inline constexpr bool widens_implicitly<integer<FR, FK>, integer<TR, TK>> =
    std::is_same_v<integer<FR, FK>, integer<TR, TK>> || implicit_widening<FR, FK, TR, TK>;

template <class A, class B, class Rep>
inline constexpr bool both_widen_to = widens_implicitly<A, integer<Rep, integer_kind::signed_int>> &&
                                      widens_implicitly<B, integer<Rep, integer_kind::signed_int>>;
/// The smallest signed integer type both A and B widen to implicitly (DINT for INT and UINT),
/// or void (LINT and ULINT; a bit string and an integer).
template <class A, class B, class Rep = std::int8_t>
struct common_signed {
  using next = std::conditional_t<sizeof(Rep) == 1, std::int16_t,
                                  std::conditional_t<sizeof(Rep) == 2, std::int32_t, std::int64_t>>;
  using type = std::conditional_t<both_widen_to<A, B, Rep>, integer<Rep, integer_kind::signed_int>,
                                  typename common_signed<A, B, next>::type>;
};
template <class A, class B>
struct common_signed<A, B, std::int64_t> {
  using type =
      std::conditional_t<both_widen_to<A, B, std::int64_t>, integer<std::int64_t, integer_kind::signed_int>, void>;
};
template <class A, class B>
using common_signed_t = typename common_signed<A, B>::type;

/// The type of an operation between values of the IEC integer types A and B: the wider one;
/// for a signed and an unsigned type, the smallest signed type that holds both (INT and UINT
/// meet as DINT, as IEC widens both to DINT implicitly); void where there is none (a bit
/// string and an integer, LINT and ULINT) or either is no IEC integer type.
template <class A, class B>
using common_integer_t = std::conditional_t<widens_implicitly<A, B>, B,
                                            std::conditional_t<widens_implicitly<B, A>, A, common_signed_t<A, B>>>;

/// Two IEC integer types that meet only in a third type (INT and UINT as DINT).
template <class A, class B>
inline constexpr bool meet_in_third_type =
    !widens_implicitly<A, B> && !widens_implicitly<B, A> && !std::is_void_v<common_signed_t<A, B>>;

/// An integer type U that an intermediate result of type T converts to only explicitly.
template <class T, class U>
concept narrower_result = is_integer<U>::value && !widens_implicitly<T, U>;

/// The register an intermediate result of IEC type T is held in: register_bits, or wider for
/// a wider T; signed for the signed integers, unsigned for the others.
template <class T>
using register_t =
    std::conditional_t<(sizeof(typename T::rep) * CHAR_BIT > static_cast<std::size_t>(register_bits)
                            ? sizeof(typename T::rep) * CHAR_BIT
                            : static_cast<std::size_t>(register_bits)) == 64,
                       std::conditional_t<T::kind == integer_kind::signed_int, std::int64_t, std::uint64_t>,
                       std::conditional_t<T::kind == integer_kind::signed_int, std::int32_t, std::uint32_t>>;

/// The value of an integer operand (a variable's or an intermediate's) in the register of IEC
/// type R: sign- or zero-extended from its own, then taken modulo 2^bits.
template <class R, class X>
constexpr register_t<R> in_register(const X& x) noexcept {
  return static_cast<register_t<R>>(x.value());
}

/// The arithmetic of registers: modulo 2^bits, never undefined behaviour.
template <class Reg>
struct register_math {
  using wide = std::make_unsigned_t<Reg>;
  static constexpr Reg add(Reg a, Reg b) noexcept {
    return static_cast<Reg>(static_cast<wide>(a) + static_cast<wide>(b));
  }
  static constexpr Reg sub(Reg a, Reg b) noexcept {
    return static_cast<Reg>(static_cast<wide>(a) - static_cast<wide>(b));
  }
  static constexpr Reg mul(Reg a, Reg b) noexcept {
    return static_cast<Reg>(static_cast<wide>(a) * static_cast<wide>(b));
  }
  static constexpr Reg neg(Reg a) noexcept { return static_cast<Reg>(wide{0} - static_cast<wide>(a)); }
  static constexpr Reg complement(Reg a) noexcept { return static_cast<Reg>(~static_cast<wide>(a)); }
  // Division truncates toward zero; the one quotient that overflows (MIN / -1) wraps.
  static constexpr Reg div(Reg a, Reg b) noexcept {
    if constexpr (std::is_signed_v<Reg>) {
      if (b == -1) return neg(a);
    }
    return static_cast<Reg>(a / b);
  }
  static constexpr Reg mod(Reg a, Reg b) noexcept {
    if constexpr (std::is_signed_v<Reg>) {
      if (b == -1) return 0;
    }
    return static_cast<Reg>(a % b);
  }
};

/// Integer division or MOD by zero: a fault, and the result 0.
inline void integer_division_by_zero() {
  fault(fault_kind::division_by_zero, "integer division or MOD by zero; the result is 0");
}

/// The diagnostic of an operation between integer types without a common type; the template
/// arguments spell both IEC names.
template <class Left, class Right>
constexpr void no_common_type_of() {
  static_assert(dependent_false<Left, Right>,
                "iecoop: these IEC integer types (spelled in `Left` and `Right`) have no implicit common type "
                "(a bit string and an integer, or LINT and ULINT); convert one operand explicitly first, e.g. "
                "WORD_TO_INT(w) or ULINT_TO_LINT(u)");
}
template <class A, class B>
constexpr nominal_t<A> no_common_type() {
  no_common_type_of<spelled_iec_name_t<nominal_t<A>>, spelled_iec_name_t<nominal_t<B>>>();
  return nominal_t<A>();
}

/// Two IEC integer values of which at least one is an intermediate result, other than two
/// intermediates of the same type (those have their own operators), or two variables that
/// meet only in a third type (INT and UINT), whose types have a common type.
template <class A, class B>
concept mixed_int_operands =
    int_value<A> && int_value<B> &&
    (is_intermediate<A>::value || is_intermediate<B>::value || meet_in_third_type<nominal_t<A>, nominal_t<B>>)&&!(
        is_intermediate<A>::value && is_intermediate<B>::value &&
        std::is_same_v<A, B>)&&!std::is_void_v<common_integer_t<nominal_t<A>, nominal_t<B>>>;

/// An IEC value of type V (or an intermediate result of type V) that does not convert
/// implicitly into T: what an assignment rejects with no_implicit_conversion.
template <class V, class T>
concept rejected_conversion = is_iec_value<V>::value && !std::is_convertible_v<const V&, T> && !std::is_same_v<V, T>;

/// Two IEC integer values whose types have no implicit common type: IEC needs an explicit
/// conversion before they meet.
template <class A, class B>
concept unrelated_integers =
    int_value<A> && int_value<B> && std::is_void_v<common_integer_t<nominal_t<A>, nominal_t<B>>>;

}  // namespace detail

/**
 * An IEC integer or bit-string type over the C++ integer `Rep`. Use the aliases: SINT, INT,
 * DINT, LINT, USINT, UINT, UDINT, ULINT, BYTE, WORD, DWORD, LWORD.
 *
 * Same size and alignment as `Rep`, trivially copyable, 0 by default. `+ - * / %` (ST's
 * MOD) and unary `-` compute in the target's registers and yield an intermediate<>, which a
 * variable takes modulo 2^bits when it is assigned; `/` and `%` truncate toward zero, and by
 * zero report fault_kind::division_by_zero and yield 0. `& | ^ ~` (AND, OR, XOR, NOT) stay in
 * the type. `x.value()` gives the C++ integer.
 *
 *     INT i = 32767;
 *     i = i + 1;            // -32768, as on a PLC: the sum 32768 is cut to 16 bits
 *     BOOL b = i + 1 > i;   // TRUE: the comparison sees the register's 32768
 *     DINT d = i;           // implicit widening
 *     i = DINT_TO_INT(d);   // narrowing is explicit (or static_cast<INT>(d))
 */
template <class Rep, integer_kind Kind>
class integer {
  static_assert(detail::cpp_integer<Rep>, "iecoop: integer<Rep, Kind> needs a built-in integer Rep");
  static_assert(std::is_signed_v<Rep> == (Kind == integer_kind::signed_int),
                "iecoop: signed IEC integers need a signed Rep, unsigned ones and bit strings an unsigned Rep");

 public:
  using rep = Rep;
  static constexpr integer_kind kind = Kind;

 private:
  // How the operators take their operands: by value for GCC, by reference for Clang. Either
  // way the same overloads match; what differs is the code. Clang copies a trivially
  // copyable class with a memcpy whose load LLVM 14 and 16 leave without type-based alias
  // information (a loop computing with a program's INT variables then reloads them after every
  // store of a block); GCC 12 turns a reference to a member into "the object's address plus
  // an offset" before inlining, which its alias analysis cannot separate from the program's
  // other variables. bench/ratio.sh measures both (docs/performance.md).
  using operand = std::conditional_t<detail::operands_by_reference, const integer&, integer>;

 public:
  constexpr integer() noexcept = default;

  /// From a C++ integer whose every value fits: implicit, at run time too.
  template <detail::cpp_integer T>
    requires detail::range_within<T, Rep>
  constexpr integer(T value) noexcept : value_(static_cast<Rep>(value)) {}  // implicit on purpose

  /// From a C++ integer constant of a wider type (`INT x = 5;`): checked at compile time.
  /// A run-time value of a wider C++ type needs an explicit IEC conversion instead, e.g.
  /// DINT_TO_INT(n).
  template <detail::cpp_integer T>
    requires(!detail::range_within<T, Rep>)
  consteval integer(T constant) : value_(static_cast<Rep>(constant)) {  // implicit on purpose
    if (!std::in_range<Rep>(constant)) {
      // The compiler shows the call's line, which must hold the whole message.
      // clang-format off
      detail::compile_error("iecoop: integer constant out of range for this IEC type; use a wider type or an explicit conversion");
      // clang-format on
    }
  }

  /// From an IEC enumeration whose base type widens to this one (<iecoop/types/enumeration.hpp>):
  /// `iVar := eState;` reads the component's value, as ST does (with 'strict' too).
  template <class E>
    requires(std::is_enum_v<E> && detail::widens_implicitly<typename detail::enum_base_of<E>::type, integer>)
  constexpr integer(E component) noexcept  // implicit: ST reads a component as its base type's value
      : value_(static_cast<Rep>(static_cast<std::underlying_type_t<E>>(component))) {}

  /// From another IEC integer type: implicit where IEC widens implicitly, explicit
  /// otherwise (keeps the low bytes, like DINT_TO_INT).
  template <class R, integer_kind K>
    requires(!std::is_same_v<integer<R, K>, integer>)
  constexpr explicit(!detail::implicit_widening<R, K, Rep, Kind>) integer(integer<R, K> other) noexcept
      : value_(static_cast<Rep>(other.value())) {}

  /// Assigning a value of a type that does not convert implicitly (`iAmount = dintVar;`,
  /// `i = d + 1;`) does not compile, and says which conversion to write instead of "no match
  /// for operator=". (std::is_convertible stays truthful: only assignment is caught.)
  template <class V>
    requires detail::rejected_conversion<V, integer>
  constexpr void operator=(const V&) noexcept {
    detail::no_implicit_conversion<detail::spelled_iec_name_t<detail::nominal_t<V>>,
                                   detail::spelled_iec_name_t<integer>>();
  }

  /// An expression assigned to the variable (`i := i + 1;`) on Clang: the register's low bits,
  /// stored as the scalar. (Through a temporary INT and its copy, Clang copies with a memcpy,
  /// whose store LLVM 14 and 16 leave without type-based alias information. GCC does better
  /// without this: with it, it no longer vectorises a FOR loop summing an ARRAY.)
  template <class T>
    requires(detail::operands_by_reference && detail::is_integer<T>::value && detail::widens_implicitly<T, integer>)
  constexpr integer& operator=(const intermediate<T>& result) noexcept {
    value_ = static_cast<Rep>(result.value());
    return *this;
  }

  /// The value as its C++ integer type.
  [[nodiscard]] constexpr Rep value() const noexcept { return value_; }

  /// Explicit conversion to any C++ arithmetic type (but not bool: an INT is no condition).
  template <class T>
    requires(std::is_arithmetic_v<T> && !std::is_same_v<T, bool>)
  explicit constexpr operator T() const noexcept {
    return static_cast<T>(value_);
  }

  // Arithmetic: the intermediate result in the target's registers (see intermediate<T>).
  friend constexpr intermediate<integer> operator+(operand a, operand b) noexcept {
    return reg(math::add(in_reg(a), in_reg(b)));
  }
  friend constexpr intermediate<integer> operator-(operand a, operand b) noexcept {
    return reg(math::sub(in_reg(a), in_reg(b)));
  }
  friend constexpr intermediate<integer> operator*(operand a, operand b) noexcept {
    return reg(math::mul(in_reg(a), in_reg(b)));
  }
  friend constexpr intermediate<integer> operator/(operand a, operand b) {
    if (b.value_ == 0) return zero_after_division_fault();
    return reg(math::div(in_reg(a), in_reg(b)));
  }
  friend constexpr intermediate<integer> operator%(operand a, operand b) {
    if (b.value_ == 0) return zero_after_division_fault();
    return reg(math::mod(in_reg(a), in_reg(b)));
  }
  friend constexpr intermediate<integer> operator-(operand a) noexcept { return reg(math::neg(in_reg(a))); }
  friend constexpr integer operator+(operand a) noexcept { return a; }

  // Bitwise: ST's AND, OR, XOR, NOT on bit strings (and, as CODESYS allows, integers), in
  // the type's own width.
  friend constexpr integer operator&(operand a, operand b) noexcept { return static_cast<Rep>(a.value_ & b.value_); }
  friend constexpr integer operator|(operand a, operand b) noexcept { return static_cast<Rep>(a.value_ | b.value_); }
  friend constexpr integer operator^(operand a, operand b) noexcept { return static_cast<Rep>(a.value_ ^ b.value_); }
  friend constexpr integer operator~(operand a) noexcept { return static_cast<Rep>(~a.value_); }

  constexpr integer& operator+=(operand b) noexcept { return *this = *this + b; }
  constexpr integer& operator-=(operand b) noexcept { return *this = *this - b; }
  constexpr integer& operator*=(operand b) noexcept { return *this = *this * b; }
  constexpr integer& operator/=(operand b) { return *this = *this / b; }
  constexpr integer& operator%=(operand b) { return *this = *this % b; }
  // `i += v` with an intermediate result or a value of another IEC type is ST's
  // `i := i + v`: combined in the register first (`i /= a * b` divides by the whole
  // product), and assigned as any result is (a wider one is rejected, as in ST).
  template <class V>
    requires(detail::int_value<V> && !std::is_same_v<V, integer>)
  constexpr integer& operator+=(const V& v) {
    *this = *this + v;
    return *this;
  }
  template <class V>
    requires(detail::int_value<V> && !std::is_same_v<V, integer>)
  constexpr integer& operator-=(const V& v) {
    *this = *this - v;
    return *this;
  }
  template <class V>
    requires(detail::int_value<V> && !std::is_same_v<V, integer>)
  constexpr integer& operator*=(const V& v) {
    *this = *this * v;
    return *this;
  }
  template <class V>
    requires(detail::int_value<V> && !std::is_same_v<V, integer>)
  constexpr integer& operator/=(const V& v) {
    *this = *this / v;
    return *this;
  }
  template <class V>
    requires(detail::int_value<V> && !std::is_same_v<V, integer>)
  constexpr integer& operator%=(const V& v) {
    *this = *this % v;
    return *this;
  }
  // A BOOL, a REAL, a TIME...: ST's `i := i + v` does not assign the result to an integer.
  template <class V>
    requires(detail::is_iec_value<V>::value && !detail::int_value<V>)
  constexpr void operator+=(const V&) {
    detail::no_implicit_conversion<detail::spelled_iec_name_t<V>, detail::spelled_iec_name_t<integer>>();
  }
  template <class V>
    requires(detail::is_iec_value<V>::value && !detail::int_value<V>)
  constexpr void operator-=(const V&) {
    detail::no_implicit_conversion<detail::spelled_iec_name_t<V>, detail::spelled_iec_name_t<integer>>();
  }
  template <class V>
    requires(detail::is_iec_value<V>::value && !detail::int_value<V>)
  constexpr void operator*=(const V&) {
    detail::no_implicit_conversion<detail::spelled_iec_name_t<V>, detail::spelled_iec_name_t<integer>>();
  }
  template <class V>
    requires(detail::is_iec_value<V>::value && !detail::int_value<V>)
  constexpr void operator/=(const V&) {
    detail::no_implicit_conversion<detail::spelled_iec_name_t<V>, detail::spelled_iec_name_t<integer>>();
  }
  template <class V>
    requires(detail::is_iec_value<V>::value && !detail::int_value<V>)
  constexpr void operator%=(const V&) {
    detail::no_implicit_conversion<detail::spelled_iec_name_t<V>, detail::spelled_iec_name_t<integer>>();
  }
  constexpr integer& operator&=(operand b) noexcept { return *this = *this & b; }
  constexpr integer& operator|=(operand b) noexcept { return *this = *this | b; }
  constexpr integer& operator^=(operand b) noexcept { return *this = *this ^ b; }
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

  // Comparison with the same type (and, through implicit widening, with narrower types):
  // a BOOL, as in ST.
  friend constexpr BOOL operator==(operand a, operand b) noexcept { return BOOL(a.value_ == b.value_); }
  friend constexpr BOOL operator!=(operand a, operand b) noexcept { return BOOL(a.value_ != b.value_); }
  friend constexpr BOOL operator<(operand a, operand b) noexcept { return BOOL(a.value_ < b.value_); }
  friend constexpr BOOL operator<=(operand a, operand b) noexcept { return BOOL(a.value_ <= b.value_); }
  friend constexpr BOOL operator>(operand a, operand b) noexcept { return BOOL(a.value_ > b.value_); }
  friend constexpr BOOL operator>=(operand a, operand b) noexcept { return BOOL(a.value_ >= b.value_); }
  friend constexpr std::strong_ordering operator<=>(operand a, operand b) noexcept { return a.value_ <=> b.value_; }

 private:
  using math = detail::register_math<detail::register_t<integer>>;
  static constexpr detail::register_t<integer> in_reg(operand x) noexcept { return detail::in_register<integer>(x); }
  static constexpr intermediate<integer> reg(detail::register_t<integer> r) noexcept {
    return intermediate<integer>::from_register(r);
  }
  static intermediate<integer> zero_after_division_fault() {
    detail::integer_division_by_zero();
    return intermediate<integer>();
  }

  friend struct detail::scalar_access;
  Rep value_ = 0;
};

template <class Rep, integer_kind Kind>
struct detail::is_scalar_wrapper<integer<Rep, Kind>> : std::true_type {};
template <class Rep, integer_kind Kind>
struct detail::is_iec_value<integer<Rep, Kind>> : std::true_type {};

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

template <>
struct detail::iec_name<SINT> {
  static constexpr std::string_view value = "SINT";
};
template <>
struct detail::iec_name<INT> {
  static constexpr std::string_view value = "INT";
};
template <>
struct detail::iec_name<DINT> {
  static constexpr std::string_view value = "DINT";
};
template <>
struct detail::iec_name<LINT> {
  static constexpr std::string_view value = "LINT";
};
template <>
struct detail::iec_name<USINT> {
  static constexpr std::string_view value = "USINT";
};
template <>
struct detail::iec_name<UINT> {
  static constexpr std::string_view value = "UINT";
};
template <>
struct detail::iec_name<UDINT> {
  static constexpr std::string_view value = "UDINT";
};
template <>
struct detail::iec_name<ULINT> {
  static constexpr std::string_view value = "ULINT";
};
template <>
struct detail::iec_name<BYTE> {
  static constexpr std::string_view value = "BYTE";
};
template <>
struct detail::iec_name<WORD> {
  static constexpr std::string_view value = "WORD";
};
template <>
struct detail::iec_name<DWORD> {
  static constexpr std::string_view value = "DWORD";
};
template <>
struct detail::iec_name<LWORD> {
  static constexpr std::string_view value = "LWORD";
};

// ---------------------------------------------------------------------------------------
// Intermediate results

/**
 * The result of an integer operation of IEC type T, as CODESYS computes it: in a register of
 * the target, `register_bits` wide (32, or 64 on a 64-bit target; wider where T is), signed
 * for the signed types and unsigned for the others, and not cut to T's width. It is cut —
 * the low bits kept — when it is assigned to a variable, passed to a parameter, or converted
 * (`TO_WORD(w + 1)`); comparisons, divisions and further operations see the whole register:
 *
 *     wVar1 := 65535; wVar2 := 0;
 *     bVar1 := (wVar1 + 1) = wVar2;       // FALSE: 65536 <> 0
 *     wVar3 := wVar1 + 1;                 // 0
 *     bVar1 := TO_WORD(wVar1 + 1) = wVar2; // TRUE
 *     iVar := (iVar + 10) / 2;            // 16388 for iVar = 32767, not -16374
 *
 * It converts implicitly to T and to every type T widens to implicitly (INT + 1 into a DINT
 * keeps 32768), to REAL/LREAL where T does, and explicitly to the other integer types.
 * `value()` is the register as a C++ integer. Registers wrap modulo 2^bits.
 */
template <class T>
class intermediate {
  static_assert(detail::is_integer<T>::value, "iecoop: intermediate<T> is the result of an IEC integer type T");

 public:
  using nominal_type = T;
  using rep = detail::register_t<T>;
  static constexpr int bits = static_cast<int>(sizeof(rep) * CHAR_BIT);

  constexpr intermediate() noexcept = default;
  /// The value of a variable of type T.
  constexpr intermediate(T value) noexcept
      : value_(detail::in_register<T>(value)) {}  // implicit: a value is an expression
  /// A C++ integer constant in an expression (`(i + 1) * 2`): checked against T while compiling.
  template <detail::cpp_integer C>
  consteval intermediate(C constant) : value_(static_cast<rep>(constant)) {  // implicit on purpose
    if (!std::in_range<typename T::rep>(constant)) {
      // The compiler shows the call's line, which must hold the whole message.
      // clang-format off
      detail::compile_error("iecoop: integer constant out of range for this IEC type; use a wider type or an explicit conversion");
      // clang-format on
    }
  }
  /// A register holding `r`.
  static constexpr intermediate from_register(rep r) noexcept {
    intermediate x;
    x.value_ = r;
    return x;
  }

  /// The register as a C++ integer.
  [[nodiscard]] constexpr rep value() const noexcept { return value_; }

  /// To T, or a type T widens to implicitly: the register's low bits (as an assignment in ST).
  template <class U>
    requires(detail::is_integer<U>::value && detail::widens_implicitly<T, U>)
  constexpr operator U() const noexcept {  // implicit: ST assigns an expression to its variable
    return U(static_cast<typename U::rep>(value_));
  }
  /// To another integer type: explicit (keeps the low bits, like DINT_TO_INT).
  template <class U>
    requires detail::narrower_result<T, U>
  explicit constexpr operator U() const noexcept {
    return U(static_cast<typename U::rep>(value_));
  }
  /// To REAL or LREAL where T converts implicitly: the register's value (no cut).
  template <class R>
    requires std::is_convertible_v<T, real<R>>
  constexpr operator real<R>() const noexcept {  // implicit on purpose
    return real<R>(static_cast<R>(value_));
  }
  /// To a C++ arithmetic type (not bool): explicit.
  template <class C>
    requires(std::is_arithmetic_v<C> && !std::is_same_v<C, bool>)
  explicit constexpr operator C() const noexcept {
    return static_cast<C>(value_);
  }

  friend constexpr intermediate operator+(intermediate a, intermediate b) noexcept {
    return from_register(math::add(a.value_, b.value_));
  }
  friend constexpr intermediate operator-(intermediate a, intermediate b) noexcept {
    return from_register(math::sub(a.value_, b.value_));
  }
  friend constexpr intermediate operator*(intermediate a, intermediate b) noexcept {
    return from_register(math::mul(a.value_, b.value_));
  }
  friend constexpr intermediate operator/(intermediate a, intermediate b) {
    if (b.value_ == 0) return zero_after_division_fault();
    return from_register(math::div(a.value_, b.value_));
  }
  friend constexpr intermediate operator%(intermediate a, intermediate b) {
    if (b.value_ == 0) return zero_after_division_fault();
    return from_register(math::mod(a.value_, b.value_));
  }
  friend constexpr intermediate operator&(intermediate a, intermediate b) noexcept {
    return from_register(static_cast<rep>(a.value_ & b.value_));
  }
  friend constexpr intermediate operator|(intermediate a, intermediate b) noexcept {
    return from_register(static_cast<rep>(a.value_ | b.value_));
  }
  friend constexpr intermediate operator^(intermediate a, intermediate b) noexcept {
    return from_register(static_cast<rep>(a.value_ ^ b.value_));
  }
  friend constexpr intermediate operator-(intermediate a) noexcept { return from_register(math::neg(a.value_)); }
  friend constexpr intermediate operator+(intermediate a) noexcept { return a; }
  friend constexpr intermediate operator~(intermediate a) noexcept { return from_register(math::complement(a.value_)); }

  friend constexpr BOOL operator==(intermediate a, intermediate b) noexcept { return BOOL(a.value_ == b.value_); }
  friend constexpr BOOL operator!=(intermediate a, intermediate b) noexcept { return BOOL(a.value_ != b.value_); }
  friend constexpr BOOL operator<(intermediate a, intermediate b) noexcept { return BOOL(a.value_ < b.value_); }
  friend constexpr BOOL operator<=(intermediate a, intermediate b) noexcept { return BOOL(a.value_ <= b.value_); }
  friend constexpr BOOL operator>(intermediate a, intermediate b) noexcept { return BOOL(a.value_ > b.value_); }
  friend constexpr BOOL operator>=(intermediate a, intermediate b) noexcept { return BOOL(a.value_ >= b.value_); }
  friend constexpr std::strong_ordering operator<=>(intermediate a, intermediate b) noexcept {
    return a.value_ <=> b.value_;
  }

 private:
  using math = detail::register_math<rep>;
  static intermediate zero_after_division_fault() {
    detail::integer_division_by_zero();
    return intermediate();
  }

  rep value_ = 0;
};

template <class T>
struct detail::is_iec_value<intermediate<T>> : std::true_type {};

// An IEC integer (a variable's, or an intermediate result's register) compared with a C++
// integer: the mathematical values, without conversion, so INT(-1) < 4000000000u is TRUE and
// `(us - 1) <> 255` sees the register's 16#FFFFFFFF. A BOOL, as every ST comparison.
template <class X, class C>
  requires(detail::int_value<X> && detail::cpp_integer<C>)
constexpr BOOL operator==(const X& a, C b) noexcept {
  return BOOL(std::cmp_equal(a.value(), b));
}
template <class C, class X>
  requires(detail::cpp_integer<C> && detail::int_value<X>)
constexpr BOOL operator==(C a, const X& b) noexcept {
  return BOOL(std::cmp_equal(a, b.value()));
}
template <class X, class C>
  requires(detail::int_value<X> && detail::cpp_integer<C>)
constexpr BOOL operator!=(const X& a, C b) noexcept {
  return BOOL(std::cmp_not_equal(a.value(), b));
}
template <class C, class X>
  requires(detail::cpp_integer<C> && detail::int_value<X>)
constexpr BOOL operator!=(C a, const X& b) noexcept {
  return BOOL(std::cmp_not_equal(a, b.value()));
}
template <class X, class C>
  requires(detail::int_value<X> && detail::cpp_integer<C>)
constexpr BOOL operator<(const X& a, C b) noexcept {
  return BOOL(std::cmp_less(a.value(), b));
}
template <class C, class X>
  requires(detail::cpp_integer<C> && detail::int_value<X>)
constexpr BOOL operator<(C a, const X& b) noexcept {
  return BOOL(std::cmp_less(a, b.value()));
}
template <class X, class C>
  requires(detail::int_value<X> && detail::cpp_integer<C>)
constexpr BOOL operator<=(const X& a, C b) noexcept {
  return BOOL(std::cmp_less_equal(a.value(), b));
}
template <class C, class X>
  requires(detail::cpp_integer<C> && detail::int_value<X>)
constexpr BOOL operator<=(C a, const X& b) noexcept {
  return BOOL(std::cmp_less_equal(a, b.value()));
}
template <class X, class C>
  requires(detail::int_value<X> && detail::cpp_integer<C>)
constexpr BOOL operator>(const X& a, C b) noexcept {
  return BOOL(std::cmp_greater(a.value(), b));
}
template <class C, class X>
  requires(detail::cpp_integer<C> && detail::int_value<X>)
constexpr BOOL operator>(C a, const X& b) noexcept {
  return BOOL(std::cmp_greater(a, b.value()));
}
template <class X, class C>
  requires(detail::int_value<X> && detail::cpp_integer<C>)
constexpr BOOL operator>=(const X& a, C b) noexcept {
  return BOOL(std::cmp_greater_equal(a.value(), b));
}
template <class C, class X>
  requires(detail::cpp_integer<C> && detail::int_value<X>)
constexpr BOOL operator>=(C a, const X& b) noexcept {
  return BOOL(std::cmp_greater_equal(a, b.value()));
}
template <class X, class C>
  requires(detail::int_value<X> && detail::cpp_integer<C>)
constexpr std::strong_ordering operator<=>(const X& a, C b) noexcept {
  if (std::cmp_less(a.value(), b)) return std::strong_ordering::less;
  if (std::cmp_greater(a.value(), b)) return std::strong_ordering::greater;
  return std::strong_ordering::equal;
}

namespace detail {

/// Two integer values of which one is (or both are) intermediate, in the register of their
/// common type C.
template <class A, class B>
using mixed_common_t = common_integer_t<nominal_t<A>, nominal_t<B>>;

}  // namespace detail

// Operations between an intermediate and a variable, or two intermediates of different
// types: computed in the register of their common type, as in ST (INT + DINT is a DINT).
// Templates with exact matches, so that neither operand is first cut to the other's type.
template <class A, class B>
  requires detail::mixed_int_operands<A, B>
constexpr intermediate<detail::mixed_common_t<A, B>> operator+(const A& a, const B& b) noexcept {
  using C = detail::mixed_common_t<A, B>;
  return intermediate<C>::from_register(detail::in_register<C>(a)) +
         intermediate<C>::from_register(detail::in_register<C>(b));
}
template <class A, class B>
  requires detail::mixed_int_operands<A, B>
constexpr intermediate<detail::mixed_common_t<A, B>> operator-(const A& a, const B& b) noexcept {
  using C = detail::mixed_common_t<A, B>;
  return intermediate<C>::from_register(detail::in_register<C>(a)) -
         intermediate<C>::from_register(detail::in_register<C>(b));
}
template <class A, class B>
  requires detail::mixed_int_operands<A, B>
constexpr intermediate<detail::mixed_common_t<A, B>> operator*(const A& a, const B& b) noexcept {
  using C = detail::mixed_common_t<A, B>;
  return intermediate<C>::from_register(detail::in_register<C>(a)) *
         intermediate<C>::from_register(detail::in_register<C>(b));
}
template <class A, class B>
  requires detail::mixed_int_operands<A, B>
constexpr intermediate<detail::mixed_common_t<A, B>> operator/(const A& a, const B& b) {
  using C = detail::mixed_common_t<A, B>;
  return intermediate<C>::from_register(detail::in_register<C>(a)) /
         intermediate<C>::from_register(detail::in_register<C>(b));
}
template <class A, class B>
  requires detail::mixed_int_operands<A, B>
constexpr intermediate<detail::mixed_common_t<A, B>> operator%(const A& a, const B& b) {
  using C = detail::mixed_common_t<A, B>;
  return intermediate<C>::from_register(detail::in_register<C>(a)) %
         intermediate<C>::from_register(detail::in_register<C>(b));
}
template <class A, class B>
  requires detail::mixed_int_operands<A, B>
constexpr intermediate<detail::mixed_common_t<A, B>> operator&(const A& a, const B& b) noexcept {
  using C = detail::mixed_common_t<A, B>;
  return intermediate<C>::from_register(detail::in_register<C>(a)) &
         intermediate<C>::from_register(detail::in_register<C>(b));
}
template <class A, class B>
  requires detail::mixed_int_operands<A, B>
constexpr intermediate<detail::mixed_common_t<A, B>> operator|(const A& a, const B& b) noexcept {
  using C = detail::mixed_common_t<A, B>;
  return intermediate<C>::from_register(detail::in_register<C>(a)) |
         intermediate<C>::from_register(detail::in_register<C>(b));
}
template <class A, class B>
  requires detail::mixed_int_operands<A, B>
constexpr intermediate<detail::mixed_common_t<A, B>> operator^(const A& a, const B& b) noexcept {
  using C = detail::mixed_common_t<A, B>;
  return intermediate<C>::from_register(detail::in_register<C>(a)) ^
         intermediate<C>::from_register(detail::in_register<C>(b));
}
template <class A, class B>
  requires detail::mixed_int_operands<A, B>
constexpr BOOL operator==(const A& a, const B& b) noexcept {
  using C = detail::mixed_common_t<A, B>;
  return BOOL(detail::in_register<C>(a) == detail::in_register<C>(b));
}
template <class A, class B>
  requires detail::mixed_int_operands<A, B>
constexpr BOOL operator!=(const A& a, const B& b) noexcept {
  using C = detail::mixed_common_t<A, B>;
  return BOOL(detail::in_register<C>(a) != detail::in_register<C>(b));
}
template <class A, class B>
  requires detail::mixed_int_operands<A, B>
constexpr BOOL operator<(const A& a, const B& b) noexcept {
  using C = detail::mixed_common_t<A, B>;
  return BOOL(detail::in_register<C>(a) < detail::in_register<C>(b));
}
template <class A, class B>
  requires detail::mixed_int_operands<A, B>
constexpr BOOL operator<=(const A& a, const B& b) noexcept {
  using C = detail::mixed_common_t<A, B>;
  return BOOL(detail::in_register<C>(a) <= detail::in_register<C>(b));
}
template <class A, class B>
  requires detail::mixed_int_operands<A, B>
constexpr BOOL operator>(const A& a, const B& b) noexcept {
  using C = detail::mixed_common_t<A, B>;
  return BOOL(detail::in_register<C>(a) > detail::in_register<C>(b));
}
template <class A, class B>
  requires detail::mixed_int_operands<A, B>
constexpr BOOL operator>=(const A& a, const B& b) noexcept {
  using C = detail::mixed_common_t<A, B>;
  return BOOL(detail::in_register<C>(a) >= detail::in_register<C>(b));
}
template <class A, class B>
  requires detail::mixed_int_operands<A, B>
constexpr std::strong_ordering operator<=>(const A& a, const B& b) noexcept {
  using C = detail::mixed_common_t<A, B>;
  return detail::in_register<C>(a) <=> detail::in_register<C>(b);
}

// Arithmetic, bitwise operations and comparisons between unrelated integer types: rejected
// with a message instead of an unhelpful "no match for operator". Each returns a value of a
// plausible type, so that the message is the only error.
template <class A, class B>
  requires detail::unrelated_integers<A, B>
detail::nominal_t<A> operator+(const A&, const B&) {
  return detail::no_common_type<A, B>();
}
template <class A, class B>
  requires detail::unrelated_integers<A, B>
detail::nominal_t<A> operator-(const A&, const B&) {
  return detail::no_common_type<A, B>();
}
template <class A, class B>
  requires detail::unrelated_integers<A, B>
detail::nominal_t<A> operator*(const A&, const B&) {
  return detail::no_common_type<A, B>();
}
template <class A, class B>
  requires detail::unrelated_integers<A, B>
detail::nominal_t<A> operator/(const A&, const B&) {
  return detail::no_common_type<A, B>();
}
template <class A, class B>
  requires detail::unrelated_integers<A, B>
detail::nominal_t<A> operator%(const A&, const B&) {
  return detail::no_common_type<A, B>();
}
template <class A, class B>
  requires detail::unrelated_integers<A, B>
detail::nominal_t<A> operator&(const A&, const B&) {
  return detail::no_common_type<A, B>();
}
template <class A, class B>
  requires detail::unrelated_integers<A, B>
detail::nominal_t<A> operator|(const A&, const B&) {
  return detail::no_common_type<A, B>();
}
template <class A, class B>
  requires detail::unrelated_integers<A, B>
detail::nominal_t<A> operator^(const A&, const B&) {
  return detail::no_common_type<A, B>();
}
template <class A, class B>
  requires detail::unrelated_integers<A, B>
BOOL operator==(const A&, const B&) {
  return BOOL(detail::no_common_type<A, B>() == detail::nominal_t<A>());
}
template <class A, class B>
  requires detail::unrelated_integers<A, B>
BOOL operator!=(const A&, const B&) {
  return BOOL(detail::no_common_type<A, B>() == detail::nominal_t<A>());
}
template <class A, class B>
  requires detail::unrelated_integers<A, B>
BOOL operator<(const A&, const B&) {
  return BOOL(detail::no_common_type<A, B>() == detail::nominal_t<A>());
}
template <class A, class B>
  requires detail::unrelated_integers<A, B>
BOOL operator<=(const A&, const B&) {
  return BOOL(detail::no_common_type<A, B>() == detail::nominal_t<A>());
}
template <class A, class B>
  requires detail::unrelated_integers<A, B>
BOOL operator>(const A&, const B&) {
  return BOOL(detail::no_common_type<A, B>() == detail::nominal_t<A>());
}
template <class A, class B>
  requires detail::unrelated_integers<A, B>
BOOL operator>=(const A&, const B&) {
  return BOOL(detail::no_common_type<A, B>() == detail::nominal_t<A>());
}
template <class A, class B>
  requires detail::unrelated_integers<A, B>
std::strong_ordering operator<=>(const A&, const B&) {
  return detail::no_common_type<A, B>().value() <=> 0;
}

// ---------------------------------------------------------------------------------------
// REAL and LREAL

namespace detail {
/// What a REAL compares with: C++ numbers, REAL/LREAL, and the IEC integers it represents
/// exactly (INT with REAL, DINT with LREAL).
template <class Rep, class U>
concept real_comparand = (std::is_arithmetic_v<U> && !std::is_same_v<U, bool>) || is_real<U>::value ||
                         ((is_integer<U>::value || is_intermediate<U>::value) && std::is_convertible_v<U, real<Rep>>);
/// The same, on the left of a REAL (a REAL there is the other operator's left operand). Not
/// defined through real_comparand: a constraint that subsumes the other would make C++ prefer
/// the reversed candidate of `r == 1.0`, which must return bool.
template <class Rep, class U>
concept real_left_comparand =
    !is_real<U>::value &&
    ((std::is_arithmetic_v<U> && !std::is_same_v<U, bool>) ||
     ((is_integer<U>::value || is_intermediate<U>::value) && std::is_convertible_v<U, real<Rep>>));

/// The right operand of a REAL's `+=`: a C++ number (a constant), a REAL no wider, or an
/// integer value the type holds exactly.
template <class Rep, class U>
concept real_compound_operand =
    (std::is_arithmetic_v<U> && !std::is_same_v<U, bool>) ||
    (is_real<U>::value && sizeof(typename U::rep) <= sizeof(Rep)) ||
    ((is_integer<U>::value || is_intermediate<U>::value) && std::is_convertible_v<nominal_t<U>, real<Rep>>);
/// Any other IEC value (a BOOL, a DINT beside a REAL, an LREAL, a TIME): rejected.
template <class Rep, class U>
concept rejected_real_operand = (is_iec_value<U>::value || is_intermediate<U>::value) && !real_compound_operand<Rep, U>;
template <class Rep, class U>
constexpr void reject_real_operand() {
  no_implicit_conversion<spelled_iec_name_t<nominal_t<U>>, spelled_iec_name_t<real<Rep>>>();
}

/// A comparand as a C++ number: a REAL's float, an integer's value in the REAL's type (exact),
/// a C++ number itself.
template <class Rep, class U>
constexpr auto real_operand(const U& u) noexcept {
  if constexpr (is_real<U>::value) {
    return u.value();
  } else if constexpr (is_integer<U>::value || is_intermediate<U>::value) {
    return static_cast<Rep>(u.value());
  } else {
    return u;
  }
}
}  // namespace detail

/**
 * IEC REAL (`real<float>`) and LREAL (`real<double>`): IEEE 754, 0.0 by default.
 *
 * Behaves as the C++ floating type it wraps (it converts to it implicitly, so `r * 2.0f`,
 * `std::sqrt(r)` work) and adds what C++'s float lacks for PLC code: zero-initialisation, a
 * distinct type for formatting, comparisons that yield BOOL, and IEC's conversion rules:
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
  constexpr real(T value) noexcept : value_(static_cast<Rep>(value)) {}  // implicit on purpose
  /// From a narrower floating type: REAL -> LREAL is implicit; LREAL -> REAL explicit.
  template <class R>
    requires(!std::is_same_v<R, Rep>)
  constexpr explicit(sizeof(R) > sizeof(Rep)) real(real<R> other) noexcept : value_(static_cast<Rep>(other.value())) {}
  /// From IEC integers the type represents exactly (INT -> REAL, DINT -> LREAL).
  template <class R, integer_kind K>
    requires(K != integer_kind::bit_string && std::numeric_limits<R>::digits <= std::numeric_limits<Rep>::digits)
  constexpr real(integer<R, K> value) noexcept : value_(static_cast<Rep>(value.value())) {}  // implicit on purpose

  /// Assigning a value of another IEC type that does not convert implicitly (`r = l;` for an
  /// LREAL, `r = i * 2.5;`, `r = b;` for a BOOL): rejected, naming the conversion to write.
  template <class V>
    requires(detail::is_iec_value<V>::value && !detail::is_intermediate<V>::value &&
             !std::is_convertible_v<const V&, real>)
  constexpr void operator=(const V&) noexcept {
    detail::no_implicit_conversion<detail::spelled_iec_name_t<V>, detail::spelled_iec_name_t<real>>();
  }
  template <class V>
    requires(detail::is_intermediate<V>::value && !std::is_convertible_v<const V&, real>)
  constexpr void operator=(const V&) noexcept {
    detail::no_implicit_conversion<detail::spelled_iec_name_t<detail::nominal_t<V>>,
                                   detail::spelled_iec_name_t<real>>();
  }

  constexpr operator Rep() const noexcept { return value_; }  // implicit: behaves as its float
  [[nodiscard]] constexpr Rep value() const noexcept { return value_; }

  // `r += v` is ST's `r := r + v`: v a REAL of this width or narrower, an integer the type
  // holds exactly (INT into REAL), an intermediate result of one, or a C++ number (a
  // constant). Anything else is rejected as the assignment `r := r + v` would be.
  template <class U>
    requires detail::real_compound_operand<Rep, U>
  constexpr real& operator+=(const U& b) noexcept {
    value_ = static_cast<Rep>(value_ + detail::real_operand<Rep>(b));
    return *this;
  }
  template <class U>
    requires detail::real_compound_operand<Rep, U>
  constexpr real& operator-=(const U& b) noexcept {
    value_ = static_cast<Rep>(value_ - detail::real_operand<Rep>(b));
    return *this;
  }
  template <class U>
    requires detail::real_compound_operand<Rep, U>
  constexpr real& operator*=(const U& b) noexcept {
    value_ = static_cast<Rep>(value_ * detail::real_operand<Rep>(b));
    return *this;
  }
  template <class U>
    requires detail::real_compound_operand<Rep, U>
  constexpr real& operator/=(const U& b) noexcept {
    value_ = static_cast<Rep>(value_ / detail::real_operand<Rep>(b));
    return *this;
  }
  template <class U>
    requires detail::rejected_real_operand<Rep, U>
  constexpr void operator+=(const U&) noexcept {
    detail::reject_real_operand<Rep, U>();
  }
  template <class U>
    requires detail::rejected_real_operand<Rep, U>
  constexpr void operator-=(const U&) noexcept {
    detail::reject_real_operand<Rep, U>();
  }
  template <class U>
    requires detail::rejected_real_operand<Rep, U>
  constexpr void operator*=(const U&) noexcept {
    detail::reject_real_operand<Rep, U>();
  }
  template <class U>
    requires detail::rejected_real_operand<Rep, U>
  constexpr void operator/=(const U&) noexcept {
    detail::reject_real_operand<Rep, U>();
  }

  // Comparisons yield BOOL (templates: exact matches, chosen over C++'s own float operators).
  template <class U>
    requires detail::real_comparand<Rep, U>
  friend constexpr BOOL operator==(const real& a, const U& b) noexcept {
    return BOOL(a.value_ == detail::real_operand<Rep>(b));
  }
  template <class U>
    requires detail::real_left_comparand<Rep, U>
  friend constexpr BOOL operator==(const U& a, const real& b) noexcept {
    return BOOL(detail::real_operand<Rep>(a) == b.value_);
  }
  template <class U>
    requires detail::real_comparand<Rep, U>
  friend constexpr BOOL operator!=(const real& a, const U& b) noexcept {
    return BOOL(a.value_ != detail::real_operand<Rep>(b));
  }
  template <class U>
    requires detail::real_left_comparand<Rep, U>
  friend constexpr BOOL operator!=(const U& a, const real& b) noexcept {
    return BOOL(detail::real_operand<Rep>(a) != b.value_);
  }
  template <class U>
    requires detail::real_comparand<Rep, U>
  friend constexpr BOOL operator<(const real& a, const U& b) noexcept {
    return BOOL(a.value_ < detail::real_operand<Rep>(b));
  }
  template <class U>
    requires detail::real_left_comparand<Rep, U>
  friend constexpr BOOL operator<(const U& a, const real& b) noexcept {
    return BOOL(detail::real_operand<Rep>(a) < b.value_);
  }
  template <class U>
    requires detail::real_comparand<Rep, U>
  friend constexpr BOOL operator<=(const real& a, const U& b) noexcept {
    return BOOL(a.value_ <= detail::real_operand<Rep>(b));
  }
  template <class U>
    requires detail::real_left_comparand<Rep, U>
  friend constexpr BOOL operator<=(const U& a, const real& b) noexcept {
    return BOOL(detail::real_operand<Rep>(a) <= b.value_);
  }
  template <class U>
    requires detail::real_comparand<Rep, U>
  friend constexpr BOOL operator>(const real& a, const U& b) noexcept {
    return BOOL(a.value_ > detail::real_operand<Rep>(b));
  }
  template <class U>
    requires detail::real_left_comparand<Rep, U>
  friend constexpr BOOL operator>(const U& a, const real& b) noexcept {
    return BOOL(detail::real_operand<Rep>(a) > b.value_);
  }
  template <class U>
    requires detail::real_comparand<Rep, U>
  friend constexpr BOOL operator>=(const real& a, const U& b) noexcept {
    return BOOL(a.value_ >= detail::real_operand<Rep>(b));
  }
  template <class U>
    requires detail::real_left_comparand<Rep, U>
  friend constexpr BOOL operator>=(const U& a, const real& b) noexcept {
    return BOOL(detail::real_operand<Rep>(a) >= b.value_);
  }

 private:
  friend struct detail::scalar_access;
  Rep value_ = 0;
};

template <class Rep>
struct detail::is_scalar_wrapper<real<Rep>> : std::true_type {};
template <class Rep>
struct detail::is_iec_value<real<Rep>> : std::true_type {};

using REAL = real<float>;
using LREAL = real<double>;
template <>
struct detail::iec_name<REAL> {
  static constexpr std::string_view value = "REAL";
};
template <>
struct detail::iec_name<LREAL> {
  static constexpr std::string_view value = "LREAL";
};

// ---------------------------------------------------------------------------------------
// REAL with integers

namespace detail {

/// The floating type an integer operand meets, or void: a REAL/LREAL's own, or a C++ float
/// (REAL) or double (LREAL) constant.
template <class X>
struct real_side {
  using type = void;
};
template <class R>
struct real_side<real<R>> {
  using type = R;
};
template <>
struct real_side<float> {
  using type = float;
};
template <>
struct real_side<double> {
  using type = double;
};

/// An IEC integer value (a variable's, or an intermediate result) beside a REAL/LREAL (or a
/// C++ float/double): ST converts the integer implicitly where the real type holds it exactly
/// (INT with REAL, DINT with LREAL), and computes in the real type.
template <class I, class F>
concept integer_with_real =
    (is_integer<I>::value || is_intermediate<I>::value) && !std::is_void_v<typename real_side<F>::type> &&
    std::is_convertible_v<nominal_t<I>, real<typename real_side<F>::type>>;
template <class A, class B>
concept real_mix = integer_with_real<A, B> || integer_with_real<B, A>;
/// An IEC integer value beside a REAL/LREAL that cannot hold it exactly (DINT with REAL).
template <class I, class F>
concept inexact_integer_with_real =
    (is_integer<I>::value || is_intermediate<I>::value) && !std::is_void_v<typename real_side<F>::type> &&
    !std::is_convertible_v<nominal_t<I>, real<typename real_side<F>::type>>;
template <class A, class B>
concept inexact_real_mix = inexact_integer_with_real<A, B> || inexact_integer_with_real<B, A>;
template <class A, class B>
using real_mix_rep = std::conditional_t<std::is_void_v<typename real_side<A>::type>, typename real_side<B>::type,
                                        typename real_side<A>::type>;
/// The real type of an integer-with-real operation that needs a conversion (DINT * 0.5f).
template <class A, class B>
using inexact_real_t = real<real_mix_rep<A, B>>;
template <class A, class B>
constexpr inexact_real_t<A, B> no_exact_real() {
  using I = std::conditional_t<std::is_void_v<typename real_side<A>::type>, A, B>;
  no_implicit_conversion<spelled_iec_name_t<nominal_t<I>>, spelled_iec_name_t<inexact_real_t<A, B>>>();
  return inexact_real_t<A, B>();
}

template <class R, class X>
constexpr R as_real(const X& x) noexcept {
  if constexpr (is_real<X>::value) {
    return x.value();
  } else if constexpr (is_integer<X>::value || is_intermediate<X>::value) {
    return static_cast<R>(x.value());
  } else {
    return static_cast<R>(x);
  }
}

}  // namespace detail

// `r * i`, `i / 2.0`, `(i + 1) * 0.5f`: the integer converts to the real type (as ST converts
// INT to REAL and DINT to LREAL implicitly) and the result is a REAL or LREAL. An integer a
// REAL cannot hold exactly (DINT with REAL) needs a conversion, as in ST (CODESYS C0197).
template <class A, class B>
  requires detail::real_mix<A, B>
constexpr real<detail::real_mix_rep<A, B>> operator+(const A& a, const B& b) noexcept {
  using R = detail::real_mix_rep<A, B>;
  return detail::as_real<R>(a) + detail::as_real<R>(b);
}
template <class A, class B>
  requires detail::real_mix<A, B>
constexpr real<detail::real_mix_rep<A, B>> operator-(const A& a, const B& b) noexcept {
  using R = detail::real_mix_rep<A, B>;
  return detail::as_real<R>(a) - detail::as_real<R>(b);
}
template <class A, class B>
  requires detail::real_mix<A, B>
constexpr real<detail::real_mix_rep<A, B>> operator*(const A& a, const B& b) noexcept {
  using R = detail::real_mix_rep<A, B>;
  return detail::as_real<R>(a) * detail::as_real<R>(b);
}
template <class A, class B>
  requires detail::real_mix<A, B>
constexpr real<detail::real_mix_rep<A, B>> operator/(const A& a, const B& b) noexcept {
  using R = detail::real_mix_rep<A, B>;
  return detail::as_real<R>(a) / detail::as_real<R>(b);
}
// An integer the real type cannot hold exactly: rejected, naming the conversion to write.
template <class A, class B>
  requires detail::inexact_real_mix<A, B>
detail::inexact_real_t<A, B> operator+(const A&, const B&) {
  return detail::no_exact_real<A, B>();
}
template <class A, class B>
  requires detail::inexact_real_mix<A, B>
detail::inexact_real_t<A, B> operator-(const A&, const B&) {
  return detail::no_exact_real<A, B>();
}
template <class A, class B>
  requires detail::inexact_real_mix<A, B>
detail::inexact_real_t<A, B> operator*(const A&, const B&) {
  return detail::no_exact_real<A, B>();
}
template <class A, class B>
  requires detail::inexact_real_mix<A, B>
detail::inexact_real_t<A, B> operator/(const A&, const B&) {
  return detail::no_exact_real<A, B>();
}

// Comparisons of an integer with a C++ float or double constant (with a REAL they are REAL's).
template <class A, class B>
  requires(detail::real_mix<A, B> && !detail::is_real<A>::value && !detail::is_real<B>::value)
constexpr BOOL operator==(const A& a, const B& b) noexcept {
  using R = detail::real_mix_rep<A, B>;
  return BOOL(detail::as_real<R>(a) == detail::as_real<R>(b));
}
template <class A, class B>
  requires(detail::real_mix<A, B> && !detail::is_real<A>::value && !detail::is_real<B>::value)
constexpr BOOL operator!=(const A& a, const B& b) noexcept {
  using R = detail::real_mix_rep<A, B>;
  return BOOL(detail::as_real<R>(a) != detail::as_real<R>(b));
}
template <class A, class B>
  requires(detail::real_mix<A, B> && !detail::is_real<A>::value && !detail::is_real<B>::value)
constexpr BOOL operator<(const A& a, const B& b) noexcept {
  using R = detail::real_mix_rep<A, B>;
  return BOOL(detail::as_real<R>(a) < detail::as_real<R>(b));
}
template <class A, class B>
  requires(detail::real_mix<A, B> && !detail::is_real<A>::value && !detail::is_real<B>::value)
constexpr BOOL operator<=(const A& a, const B& b) noexcept {
  using R = detail::real_mix_rep<A, B>;
  return BOOL(detail::as_real<R>(a) <= detail::as_real<R>(b));
}
template <class A, class B>
  requires(detail::real_mix<A, B> && !detail::is_real<A>::value && !detail::is_real<B>::value)
constexpr BOOL operator>(const A& a, const B& b) noexcept {
  using R = detail::real_mix_rep<A, B>;
  return BOOL(detail::as_real<R>(a) > detail::as_real<R>(b));
}
template <class A, class B>
  requires(detail::real_mix<A, B> && !detail::is_real<A>::value && !detail::is_real<B>::value)
constexpr BOOL operator>=(const A& a, const B& b) noexcept {
  using R = detail::real_mix_rep<A, B>;
  return BOOL(detail::as_real<R>(a) >= detail::as_real<R>(b));
}

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
/// An intermediate result of integer arithmetic (intermediate<T>).
template <class T>
concept Intermediate = detail::is_intermediate<T>::value;

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
