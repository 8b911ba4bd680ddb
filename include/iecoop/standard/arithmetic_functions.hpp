// SPDX-License-Identifier: MIT
// iecoop/standard/arithmetic_functions.hpp — IEC 61131-3's arithmetic functions ADD, MUL, SUB,
// DIV, MOD and MOVE in function form, as the operators compute (`ADD(a, b)` is `a + b`).
//
//     iSum := ADD(i1, i2, i3);        iSum = ADD(i1, i2, i3);       (i1 + i2 + i3)
//     diQ := DIV(diA, 4);             diQ = DIV(diA, 4);
//     tTotal := ADD(tRun, T#5s);      tTotal = ADD(tRun, "T#5s"_iec);
//
// ADD and MUL are extensible (two or more inputs), SUB, DIV and MOD take two, MOVE one. The
// inputs take one type as in every generic function (detail/generic_arguments.hpp) and the
// result is what the operator gives: an integer result is an intermediate in the register (it
// wraps when assigned), a division or MOD by zero reports fault_kind::division_by_zero and gives
// 0, REAL division follows IEEE 754. MOD is for integers only, as in ST.
#pragma once

#include <utility>

#include <iecoop/config.hpp>
#include <iecoop/standard/detail/generic_arguments.hpp>
#include <iecoop/types/detail/value_operators.hpp>
#include <iecoop/types/elementary.hpp>

#include <iecoop/detail/push_macros.hpp>

namespace iecoop {

/// ADD(IN1, IN2, ...): IN1 + IN2 + ...
template <class In1, class In2, class... More>
[[nodiscard]] constexpr auto ADD(In1&& in1, In2&& in2, More&&... more) {
  using C = detail::common_argument_t<In1, In2, More...>;
  static_assert(sizeof(detail::arguments_check<In1, In2, More...>) > 0);  // reports inputs that do not meet
  return ((detail::as_common<C>(std::forward<In1>(in1)) + detail::as_common<C>(std::forward<In2>(in2))) + ... +
          detail::as_common<C>(std::forward<More>(more)));
}

/// MUL(IN1, IN2, ...): IN1 * IN2 * ...
template <class In1, class In2, class... More>
[[nodiscard]] constexpr auto MUL(In1&& in1, In2&& in2, More&&... more) {
  using C = detail::common_argument_t<In1, In2, More...>;
  static_assert(sizeof(detail::arguments_check<In1, In2, More...>) > 0);  // reports inputs that do not meet
  return ((detail::as_common<C>(std::forward<In1>(in1)) * detail::as_common<C>(std::forward<In2>(in2))) * ... *
          detail::as_common<C>(std::forward<More>(more)));
}

/// SUB(IN1, IN2): IN1 - IN2.
template <class In1, class In2>
[[nodiscard]] constexpr auto SUB(In1&& in1, In2&& in2) {
  using C = detail::common_argument_t<In1, In2>;
  static_assert(sizeof(detail::arguments_check<In1, In2>) > 0);  // reports inputs that do not meet
  return detail::as_common<C>(std::forward<In1>(in1)) - detail::as_common<C>(std::forward<In2>(in2));
}

/// DIV(IN1, IN2): IN1 / IN2; integers truncate toward zero, by 0 a fault and 0.
template <class In1, class In2>
[[nodiscard]] constexpr auto DIV(In1&& in1, In2&& in2) {
  using C = detail::common_argument_t<In1, In2>;
  static_assert(sizeof(detail::arguments_check<In1, In2>) > 0);  // reports inputs that do not meet
  return detail::as_common<C>(std::forward<In1>(in1)) / detail::as_common<C>(std::forward<In2>(in2));
}

/// MOD(IN1, IN2): the remainder of IN1 / IN2, with IN1's sign; by 0 a fault and 0. Integers only.
template <class In1, class In2>
[[nodiscard]] constexpr auto MOD(In1&& in1, In2&& in2) {
  using C = detail::common_argument_t<In1, In2>;
  static_assert(sizeof(detail::arguments_check<In1, In2>) > 0);  // reports inputs that do not meet
  static_assert(
      detail::int_value<C> || detail::cpp_integer<C>,
      "iecoop: MOD takes integers (ANY_INT), as in ST; convert REAL inputs first, e.g. MOD(REAL_TO_DINT(r), 360)");
  return detail::as_common<C>(std::forward<In1>(in1)) % detail::as_common<C>(std::forward<In2>(in2));
}

/// MOVE(IN): IN's value (ST's assignment as a function: `x := MOVE(y);` is `x := y;`).
template <class In>
[[nodiscard]] constexpr detail::argument_t<In> MOVE(const In& in) {
  return detail::argument_value(in);
}

}  // namespace iecoop

#include <iecoop/detail/pop_macros.hpp>
