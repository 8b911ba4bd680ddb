// SPDX-License-Identifier: MIT
// iecoop/types/intermediate.hpp — intermediate<T>, the result of an integer operation as CODESYS
// computes it: in a register of the target, cut to T's width only where it is assigned
// (part of <iecoop/types/elementary.hpp>).
#pragma once

#include <iecoop/types/integer.hpp>

#include <iecoop/detail/push_macros.hpp>

namespace iecoop {

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

}  // namespace iecoop

#include <iecoop/detail/pop_macros.hpp>
