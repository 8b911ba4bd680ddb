// SPDX-License-Identifier: MIT
// iecoop/types/integer.hpp — the IEC integers SINT..LINT, USINT..ULINT and bit strings
// BYTE..LWORD (integer<Rep, Kind>), computed in CODESYS's registers (part of
// <iecoop/types/elementary.hpp>). Their operations' results, intermediate<T>, are in
// <iecoop/types/intermediate.hpp>, which this header completes itself with at its end.
#pragma once

#include <iecoop/types/bool.hpp>
#include <iecoop/types/detail/elementary_traits.hpp>

#include <iecoop/detail/push_macros.hpp>

namespace iecoop {

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

// An operation's result, intermediate<T>: with it, the integers are whole.
#include <iecoop/types/intermediate.hpp>

#include <iecoop/detail/pop_macros.hpp>
