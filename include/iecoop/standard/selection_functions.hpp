// SPDX-License-Identifier: MIT
// iecoop/standard/selection_functions.hpp — IEC 61131-3's selection functions SEL, MAX, MIN,
// LIMIT and MUX, generic over every elementary type as IEC defines them.
//
//     rSpeed := LIMIT(0.0, rSetpoint, 100.0);   rSpeed = LIMIT(0.0, rSetpoint, 100.0);
//     iMax := MAX(iA, iB, iC);                  iMax = MAX(iA, iB, iC);
//     tWait := SEL(bFast, T#2s, T#500ms);       tWait = SEL(bFast, "T#2s"_iec, "T#500ms"_iec);
//     iOut := MUX(k, 10, 20, 30);               iOut = MUX(k, 10, 20, 30);
//
// The inputs take one type, the type ST's `a + b` would give them (detail/generic_arguments.hpp):
// MAX of an INT and a DINT is a DINT, of an INT and a REAL a REAL; C++ numbers take the IEC
// inputs' type. An intermediate result keeps its register (MAX(i + 1, j) of INT 32767 is 32768
// until it is assigned). Strings select as STRING of the larger capacity.
//
// C++ evaluates every argument before the call; CODESYS evaluates only the selected input of
// SEL and MUX. Where an input has a side effect (a method call), select with IF instead.
#pragma once

#include <cstddef>
#include <limits>
#include <type_traits>
#include <utility>

#include <iecoop/config.hpp>
#include <iecoop/standard/detail/generic_arguments.hpp>
#include <iecoop/types/detail/value_operators.hpp>
#include <iecoop/types/elementary.hpp>

#include <iecoop/detail/push_macros.hpp>

namespace iecoop {

namespace detail {

/// A condition: a BOOL (or a variable of one), or a C++ bool.
template <class G>
concept selector_condition = std::is_same_v<argument_t<G>, BOOL> || std::is_same_v<std::remove_cvref_t<G>, bool>;

/// MUX's K: ANY_INT or ANY_BIT (a variable of one), or a C++ integer.
template <class K>
concept mux_selector = int_value<argument_t<K>> || cpp_integer<std::remove_cvref_t<K>>;

template <class K>
constexpr long long selector_value(const K& k) {
  if constexpr (cpp_integer<K>) {
    if (std::cmp_greater(k, std::numeric_limits<long long>::max())) return -1;
    return static_cast<long long>(k);
  } else {
    const auto v = argument_value(k).value();
    if (std::cmp_greater(v, std::numeric_limits<long long>::max())) return -1;
    return static_cast<long long>(v);
  }
}

template <class C, class Pick, class X>
constexpr C select_by(Pick, X&& x) {
  return as_common<C>(std::forward<X>(x));
}
template <class C, class Pick, class X, class Y, class... Rest>
constexpr C select_by(Pick pick, X&& x, Y&& y, Rest&&... rest) {
  const C a = as_common<C>(std::forward<X>(x));
  const C b = as_common<C>(std::forward<Y>(y));
  return select_by<C>(pick, pick(a, b) ? a : b, std::forward<Rest>(rest)...);
}

}  // namespace detail

/**
 * SEL(G, IN0, IN1): IN0 if G is FALSE, IN1 if G is TRUE. G is a BOOL; IN0 and IN1 take their
 * common type.
 */
template <class G, class In0, class In1>
  requires detail::selector_condition<G>
[[nodiscard]] constexpr auto SEL(const G& g, In0&& in0, In1&& in1) {
  using C = detail::common_argument_t<In0, In1>;
  static_assert(sizeof(detail::arguments_check<In0, In1>) > 0);  // reports inputs that do not meet
  if (static_cast<bool>(detail::argument_value(g))) return detail::as_common<C>(std::forward<In1>(in1));
  return detail::as_common<C>(std::forward<In0>(in0));
}

/**
 * MAX(IN1, IN2, ...): the greatest input (IEC makes MAX extensible: two or more). Of equal
 * inputs the first; a REAL NaN input is passed on only if it comes first.
 */
template <class In1, class In2, class... More>
[[nodiscard]] constexpr auto MAX(In1&& in1, In2&& in2, More&&... more) {
  using C = detail::common_argument_t<In1, In2, More...>;
  static_assert(sizeof(detail::arguments_check<In1, In2, More...>) > 0);  // reports inputs that do not meet
  return detail::select_by<C>([](const C& a, const C& b) { return !static_cast<bool>(b > a); }, std::forward<In1>(in1),
                              std::forward<In2>(in2), std::forward<More>(more)...);
}

/**
 * MIN(IN1, IN2, ...): the smallest input (two or more). Of equal inputs the first; a REAL NaN
 * input is passed on only if it comes first.
 */
template <class In1, class In2, class... More>
[[nodiscard]] constexpr auto MIN(In1&& in1, In2&& in2, More&&... more) {
  using C = detail::common_argument_t<In1, In2, More...>;
  static_assert(sizeof(detail::arguments_check<In1, In2, More...>) > 0);  // reports inputs that do not meet
  return detail::select_by<C>([](const C& a, const C& b) { return !static_cast<bool>(b < a); }, std::forward<In1>(in1),
                              std::forward<In2>(in2), std::forward<More>(more)...);
}

/**
 * LIMIT(MN, IN, MX): IN bounded to MN..MX, defined as CODESYS and IEC define it,
 * MIN(MAX(IN, MN), MX) — so with MN > MX the result is MX.
 */
template <class Mn, class In, class Mx>
[[nodiscard]] constexpr auto LIMIT(Mn&& mn, In&& in, Mx&& mx) {
  using C = detail::common_argument_t<Mn, In, Mx>;
  static_assert(sizeof(detail::arguments_check<Mn, In, Mx>) > 0);  // reports inputs that do not meet
  return MIN(MAX(detail::as_common<C>(std::forward<In>(in)), detail::as_common<C>(std::forward<Mn>(mn))),
             detail::as_common<C>(std::forward<Mx>(mx)));
}

/**
 * MUX(K, IN0, IN1, ...): input number K, counting from 0. A K greater than the number of the
 * last input selects the last input, as CODESYS documents; so does a negative K (CODESYS
 * documents only K > n; iecoop reads K as an unsigned comparison would).
 */
template <class K, class In0, class... More>
  requires detail::mux_selector<K>
[[nodiscard]] constexpr auto MUX(const K& k, In0&& in0, More&&... more) {
  using C = detail::common_argument_t<In0, More...>;
  static_assert(sizeof(detail::arguments_check<In0, More...>) > 0);  // reports inputs that do not meet
  const C inputs[] = {detail::as_common<C>(std::forward<In0>(in0)), detail::as_common<C>(std::forward<More>(more))...};
  constexpr long long last = static_cast<long long>(sizeof...(More));
  const long long index = detail::selector_value(k);
  return inputs[index < 0 || index > last ? last : index];
}

}  // namespace iecoop

#include <iecoop/detail/pop_macros.hpp>
