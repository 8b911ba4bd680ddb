// SPDX-License-Identifier: MIT
// iecoop/types/real.hpp — IEC REAL and LREAL, and their operations with the integers
// (part of <iecoop/types/elementary.hpp>).
#pragma once

#include <iecoop/types/integer.hpp>

#include <iecoop/detail/push_macros.hpp>

namespace iecoop {

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

}  // namespace iecoop

#include <iecoop/detail/pop_macros.hpp>
