// SPDX-License-Identifier: MIT
// iecoop/standard/comparison_functions.hpp — IEC 61131-3's comparison functions GT, GE, EQ, LE,
// LT and NE in function form, as the operators compare (`GT(a, b)` is `a > b`).
//
//     bRising := GT(iC, iB, iA);       bRising = GT(iC, iB, iA);     (iC > iB AND iB > iA)
//     bSame := EQ(tA, tB);             bSame = EQ(tA, tB);
//
// GT, GE, EQ, LE and LT are extensible, as IEC defines them: with more than two inputs each
// neighbouring pair is compared and the results are ANDed. NE takes exactly two. The inputs
// take one type as in every generic function (detail/generic_arguments.hpp); the result is a
// BOOL.
#pragma once

#include <cstddef>
#include <utility>

#include <iecoop/config.hpp>
#include <iecoop/standard/detail/generic_arguments.hpp>
#include <iecoop/types/elementary.hpp>

#include <iecoop/detail/push_macros.hpp>

namespace iecoop {

namespace detail {

/// Each neighbouring pair of inputs, all of type C, compared by `holds`.
template <class C, class Holds, class... In>
constexpr BOOL compare_chain(Holds holds, In&&... in) {
  const C values[] = {as_common<C>(std::forward<In>(in))...};
  for (std::size_t i = 0; i + 1 < sizeof...(In); ++i) {
    if (!holds(values[i], values[i + 1])) return FALSE;
  }
  return TRUE;
}

}  // namespace detail

/// GT(IN1, IN2, ...): IN1 > IN2 (AND IN2 > IN3 ...): strictly decreasing.
template <class In1, class In2, class... More>
[[nodiscard]] constexpr BOOL GT(In1&& in1, In2&& in2, More&&... more) {
  using C = detail::common_argument_t<In1, In2, More...>;
  static_assert(sizeof(detail::arguments_check<In1, In2, More...>) > 0);  // reports inputs that do not meet
  return detail::compare_chain<C>([](const C& a, const C& b) { return static_cast<bool>(a > b); },
                                  std::forward<In1>(in1), std::forward<In2>(in2), std::forward<More>(more)...);
}

/// GE(IN1, IN2, ...): IN1 >= IN2 (AND IN2 >= IN3 ...): decreasing.
template <class In1, class In2, class... More>
[[nodiscard]] constexpr BOOL GE(In1&& in1, In2&& in2, More&&... more) {
  using C = detail::common_argument_t<In1, In2, More...>;
  static_assert(sizeof(detail::arguments_check<In1, In2, More...>) > 0);  // reports inputs that do not meet
  return detail::compare_chain<C>([](const C& a, const C& b) { return static_cast<bool>(a >= b); },
                                  std::forward<In1>(in1), std::forward<In2>(in2), std::forward<More>(more)...);
}

/// EQ(IN1, IN2, ...): all inputs equal.
template <class In1, class In2, class... More>
[[nodiscard]] constexpr BOOL EQ(In1&& in1, In2&& in2, More&&... more) {
  using C = detail::common_argument_t<In1, In2, More...>;
  static_assert(sizeof(detail::arguments_check<In1, In2, More...>) > 0);  // reports inputs that do not meet
  return detail::compare_chain<C>([](const C& a, const C& b) { return static_cast<bool>(a == b); },
                                  std::forward<In1>(in1), std::forward<In2>(in2), std::forward<More>(more)...);
}

/// LE(IN1, IN2, ...): IN1 <= IN2 (AND IN2 <= IN3 ...): increasing.
template <class In1, class In2, class... More>
[[nodiscard]] constexpr BOOL LE(In1&& in1, In2&& in2, More&&... more) {
  using C = detail::common_argument_t<In1, In2, More...>;
  static_assert(sizeof(detail::arguments_check<In1, In2, More...>) > 0);  // reports inputs that do not meet
  return detail::compare_chain<C>([](const C& a, const C& b) { return static_cast<bool>(a <= b); },
                                  std::forward<In1>(in1), std::forward<In2>(in2), std::forward<More>(more)...);
}

/// LT(IN1, IN2, ...): IN1 < IN2 (AND IN2 < IN3 ...): strictly increasing.
template <class In1, class In2, class... More>
[[nodiscard]] constexpr BOOL LT(In1&& in1, In2&& in2, More&&... more) {
  using C = detail::common_argument_t<In1, In2, More...>;
  static_assert(sizeof(detail::arguments_check<In1, In2, More...>) > 0);  // reports inputs that do not meet
  return detail::compare_chain<C>([](const C& a, const C& b) { return static_cast<bool>(a < b); },
                                  std::forward<In1>(in1), std::forward<In2>(in2), std::forward<More>(more)...);
}

/// NE(IN1, IN2): IN1 <> IN2 (not extensible).
template <class In1, class In2>
[[nodiscard]] constexpr BOOL NE(In1&& in1, In2&& in2) {
  using C = detail::common_argument_t<In1, In2>;
  static_assert(sizeof(detail::arguments_check<In1, In2>) > 0);  // reports inputs that do not meet
  return BOOL(
      static_cast<bool>(detail::as_common<C>(std::forward<In1>(in1)) != detail::as_common<C>(std::forward<In2>(in2))));
}

}  // namespace iecoop

#include <iecoop/detail/pop_macros.hpp>
