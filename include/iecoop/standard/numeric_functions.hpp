// SPDX-License-Identifier: MIT
// iecoop/standard/numeric_functions.hpp — IEC 61131-3's numerical functions: ABS for ANY_NUM;
// SQRT, LN, LOG, EXP, SIN, COS, TAN, ASIN, ACOS, ATAN, ATAN2 and EXPT for ANY_REAL.
//
//     rDist := SQRT(rX * rX + rY * rY);      rDist = SQRT(rX * rX + rY * rY);
//     lrArea := EXPT(rRadius, 2) * 3.14159;   lrArea = EXPT(rRadius, 2) * 3.14159;
//     iDelta := ABS(iA - iB);                 iDelta = ABS(iA - iB);
//
// - ABS of an integer is computed in the register, as `-i` is: ABS(INT#-32768) is 32768 there,
//   and -32768 once assigned to an INT (IEC integer arithmetic wraps). ABS is constexpr.
// - The REAL functions return the type of their input (REAL or LREAL), EXPT always an LREAL.
//   An integer input is taken as the REAL type it converts to implicitly (INT as REAL, DINT as
//   LREAL), as CODESYS accepts ANY_NUM there. Angles are in radians; LOG is base 10.
// - Outside a function's domain the result is IEEE 754's, as CODESYS computes on its targets:
//   SQRT(-1.0) and LN(-1.0) are NaN, LN(0.0) is minus infinity, ASIN(2.0) is NaN, EXPT of a
//   negative base to a non-integer power is NaN, EXPT(0.0, -1) is infinity. Check with
//   the result's `isnan()`/`isinf()` where an input may leave the domain.
// - These use <cmath>, which is not constexpr in C++20; they are not either.
#pragma once

#include <cmath>
#include <type_traits>

#include <iecoop/config.hpp>
#include <iecoop/standard/detail/generic_arguments.hpp>
#include <iecoop/types/detail/value_operators.hpp>
#include <iecoop/types/elementary.hpp>

#include <iecoop/detail/push_macros.hpp>

namespace iecoop {

namespace detail {

/// The REAL type an argument is computed in: its own, or for an integer the real type it
/// converts to implicitly (REAL for up to 16 bits, LREAL beyond), or LREAL for a C++ number.
template <class X, class V = argument_t<X>>
struct real_of {
  using type = LREAL;
};
template <class X, class R>
struct real_of<X, real<R>> {
  using type = real<R>;
};
template <class X, class V>
  requires int_value<V>
struct real_of<X, V> {
  using type = std::conditional_t<std::is_convertible_v<nominal_t<V>, REAL>, REAL, LREAL>;
};
template <class X>
using real_of_t = typename real_of<X>::type;

/// A numerical function's input: ANY_NUM (a variable of one, an intermediate result), or a C++
/// number.
template <class X>
concept numeric_argument = int_value<argument_t<X>> || is_real<argument_t<X>>::value || cpp_number_argument<X>;

template <class X>
constexpr auto real_rep_value(const X& x) {
  using R = typename real_of_t<X>::rep;
  if constexpr (cpp_number_argument<X>) {
    return static_cast<R>(x);
  } else {
    return static_cast<R>(argument_value(x).value());
  }
}

/// `op` on IN's value in its REAL type.
template <class X, class Op>
real_of_t<X> apply_real(const X& x, Op op) {
  using R = typename real_of_t<X>::rep;
  return real_of_t<X>(static_cast<R>(op(real_rep_value(x))));
}

}  // namespace detail

/**
 * ABS(IN): the absolute value, of IN's type. For an integer the result is computed in the
 * register (an intermediate result, like `-i`).
 */
template <class In>
  requires(detail::int_value<detail::argument_t<In>> || detail::is_real<detail::argument_t<In>>::value)
[[nodiscard]] constexpr auto ABS(const In& in) {
  const auto v = detail::argument_value(in);
  using V = std::remove_cvref_t<decltype(v)>;
  if constexpr (detail::is_real<V>::value) {
    using R = typename V::rep;
    return V(v.value() < R{0} ? -v.value() : v.value());  // -0.0 stays -0.0, as fabs does not; equal
  } else {
    const intermediate<detail::nominal_t<V>> r = v;
    return r < 0 ? -r : r;
  }
}

/// SQRT(IN): the square root; NaN for a negative IN.
template <class In>
  requires detail::numeric_argument<In>
[[nodiscard]] inline detail::real_of_t<In> SQRT(const In& in) {
  return detail::apply_real(in, [](auto x) { return std::sqrt(x); });
}

/// LN(IN): the natural logarithm; minus infinity for 0, NaN below.
template <class In>
  requires detail::numeric_argument<In>
[[nodiscard]] inline detail::real_of_t<In> LN(const In& in) {
  return detail::apply_real(in, [](auto x) { return std::log(x); });
}

/// LOG(IN): the logarithm to base 10; minus infinity for 0, NaN below.
template <class In>
  requires detail::numeric_argument<In>
[[nodiscard]] inline detail::real_of_t<In> LOG(const In& in) {
  return detail::apply_real(in, [](auto x) { return std::log10(x); });
}

/// EXP(IN): e to the power IN.
template <class In>
  requires detail::numeric_argument<In>
[[nodiscard]] inline detail::real_of_t<In> EXP(const In& in) {
  return detail::apply_real(in, [](auto x) { return std::exp(x); });
}

/// SIN(IN): the sine of IN radians.
template <class In>
  requires detail::numeric_argument<In>
[[nodiscard]] inline detail::real_of_t<In> SIN(const In& in) {
  return detail::apply_real(in, [](auto x) { return std::sin(x); });
}

/// COS(IN): the cosine of IN radians.
template <class In>
  requires detail::numeric_argument<In>
[[nodiscard]] inline detail::real_of_t<In> COS(const In& in) {
  return detail::apply_real(in, [](auto x) { return std::cos(x); });
}

/// TAN(IN): the tangent of IN radians.
template <class In>
  requires detail::numeric_argument<In>
[[nodiscard]] inline detail::real_of_t<In> TAN(const In& in) {
  return detail::apply_real(in, [](auto x) { return std::tan(x); });
}

/// ASIN(IN): the arc sine in radians, -pi/2..pi/2; NaN outside -1..1.
template <class In>
  requires detail::numeric_argument<In>
[[nodiscard]] inline detail::real_of_t<In> ASIN(const In& in) {
  return detail::apply_real(in, [](auto x) { return std::asin(x); });
}

/// ACOS(IN): the arc cosine in radians, 0..pi; NaN outside -1..1.
template <class In>
  requires detail::numeric_argument<In>
[[nodiscard]] inline detail::real_of_t<In> ACOS(const In& in) {
  return detail::apply_real(in, [](auto x) { return std::acos(x); });
}

/// ATAN(IN): the arc tangent in radians, -pi/2..pi/2.
template <class In>
  requires detail::numeric_argument<In>
[[nodiscard]] inline detail::real_of_t<In> ATAN(const In& in) {
  return detail::apply_real(in, [](auto x) { return std::atan(x); });
}

/**
 * ATAN2(Y, X): the angle of the point (X, Y) in radians, -pi..pi (the quadrant from both
 * signs). Y and X take their common REAL type.
 */
template <class Y, class X>
  requires(detail::numeric_argument<Y> && detail::numeric_argument<X>)
[[nodiscard]] inline auto ATAN2(const Y& y, const X& x) {
  using C = detail::common_argument_t<detail::real_of_t<Y>, detail::real_of_t<X>>;
  using R = typename C::rep;
  return C(
      static_cast<R>(std::atan2(static_cast<R>(detail::real_rep_value(y)), static_cast<R>(detail::real_rep_value(x)))));
}

/**
 * EXPT(IN1, IN2): IN1 to the power IN2, an LREAL whatever the inputs' types, as TwinCAT documents
 * for its CODESYS-based compiler ("return type is always LREAL"; assigning it to a REAL needs
 * LREAL_TO_REAL, where TwinCAT warns). Both inputs are any numbers; a negative base to a whole
 * power is exact in sign (EXPT(-2.0, 3) is -8.0), to a fractional power NaN; EXPT(0.0, -1) is
 * infinity; EXPT(x, 0) is 1.0, even for a NaN x.
 */
template <class In1, class In2>
  requires(detail::numeric_argument<In1> && detail::numeric_argument<In2>)
[[nodiscard]] inline LREAL EXPT(const In1& in1, const In2& in2) {
  return LREAL(
      std::pow(static_cast<double>(detail::real_rep_value(in1)), static_cast<double>(detail::real_rep_value(in2))));
}

}  // namespace iecoop

#include <iecoop/detail/pop_macros.hpp>
