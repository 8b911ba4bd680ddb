// SPDX-License-Identifier: MIT
// iecoop/standard/bit_functions.hpp — IEC 61131-3's bit-shift functions SHL, SHR, ROL, ROR and
// the bitwise functions AND, OR, XOR, NOT in function form.
//
//     wOut := SHL(wIn, 2);          wOut = SHL(wIn, 2);
//     byRot := ROL(byIn, n);        byRot = ROL(byIn, n);
//     bAll := AND(b1, b2, b3);      bAll = AND(b1, b2, b3);      (also b1 & b2 & b3)
//
// A shift works in the width of IN's type (BYTE 8 bits .. LWORD 64), as CODESYS states: SHL of
// BYTE 16#45 by 2 is 16#14, of WORD 16#0045 by 2 is 16#0114. An intermediate result
// (SHL(w + 1, 1)) is first cut to its type, as an assignment would. Integers are not shifted:
// IEC's IN is ANY_BIT; convert first (INT_TO_WORD(i)).
#pragma once

#include <concepts>
#include <cstdint>
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

/// SHL/SHR/ROL/ROR's IN: a bit string BYTE..LWORD (a variable of one, or an intermediate of one).
template <class X>
concept shift_operand = int_value<argument_t<X>> && nominal_t<argument_t<X>>::kind == integer_kind::bit_string;

/// N: ANY_INT or ANY_BIT, or a C++ integer.
template <class N>
concept shift_count = int_value<argument_t<N>> || cpp_integer<std::remove_cvref_t<N>>;

/// Reports a shift of something that is no bit string: each shift function starts with
/// `static_assert(sizeof(shift_operand_check<In>) > 0);`, so the report comes first.
template <class X>
struct shift_operand_check {
  static_assert(shift_operand<X>,
                "iecoop: SHL, SHR, ROL and ROR shift a bit string (BYTE, WORD, DWORD, LWORD); convert an integer "
                "first, e.g. SHL(INT_TO_WORD(i), 1)");
};

/// N as a signed count: negative stays negative; a count beyond 64 bits is 65.
template <class N>
constexpr long long shift_amount(const N& n) {
  const auto v = [&] {
    if constexpr (cpp_integer<N>) {
      return n;
    } else {
      return argument_value(n).value();
    }
  }();
  if (std::cmp_less(v, 0)) return -1;
  if (std::cmp_greater(v, 64)) return 65;
  return static_cast<long long>(v);
}

/// The bits of IN in its own type's width, in a 64-bit register (no promotion to int).
template <class X>
constexpr std::uint64_t shift_bits(const X& in) {
  using T = nominal_t<argument_t<X>>;
  return static_cast<typename T::rep>(argument_value(in).value());
}

/// N modulo the width, as a rotation needs it (negative N turns the other way).
template <class Rep, class N>
constexpr unsigned rotation(const N& n) {
  constexpr long long width = std::numeric_limits<Rep>::digits;
  long long v;
  if constexpr (cpp_integer<N>) {
    v = static_cast<long long>(n % static_cast<N>(width));
  } else {
    const auto raw = argument_value(n).value();
    v = static_cast<long long>(raw % static_cast<decltype(raw)>(width));
  }
  return static_cast<unsigned>(((v % width) + width) % width);
}

}  // namespace detail

namespace detail {

enum class shift_direction : bool { left, right };

/// SHL and SHR: zeros shifted in; a count at or beyond the width, or negative, gives 0.
template <shift_direction D, class In, class N>
constexpr auto shifted(const In& in, const N& n) {
  if constexpr (!shift_operand<In>) {
    return in;  // shift_operand_check has reported it
  } else {
    using T = nominal_t<argument_t<In>>;
    using Rep = typename T::rep;
    const long long count = shift_amount(n);
    if (count < 0 || count >= std::numeric_limits<Rep>::digits) return T(Rep{0});
    const std::uint64_t bits = shift_bits(in);
    return T(static_cast<Rep>(D == shift_direction::left ? bits << count : bits >> count));
  }
}

/// ROL and ROR: the count modulo the width.
template <shift_direction D, class In, class N>
constexpr auto rotated(const In& in, const N& n) {
  if constexpr (!shift_operand<In>) {
    return in;  // shift_operand_check has reported it
  } else {
    using T = nominal_t<argument_t<In>>;
    using Rep = typename T::rep;
    constexpr unsigned width = std::numeric_limits<Rep>::digits;
    const unsigned left = D == shift_direction::left ? rotation<Rep>(n) : (width - rotation<Rep>(n)) % width;
    const std::uint64_t bits = shift_bits(in);
    if (left == 0) return T(static_cast<Rep>(bits));
    return T(static_cast<Rep>((bits << left) | (bits >> (width - left))));
  }
}

}  // namespace detail

/**
 * SHL(IN, N): IN shifted left by N bits, zeros shifted in. N at or beyond the width (or
 * negative, which CODESYS reads as a large unsigned count) gives 0; CODESYS leaves this to the
 * target, IEC's definition (zero-filled) gives 0.
 */
template <class In, class N>
  requires detail::shift_count<N>
[[nodiscard]] constexpr auto SHL(const In& in, const N& n) {
  static_assert(sizeof(detail::shift_operand_check<In>) > 0);
  return detail::shifted<detail::shift_direction::left>(in, n);
}

/// SHR(IN, N): IN shifted right by N bits, zeros shifted in (bit strings have no sign). N at or
/// beyond the width, or negative, gives 0.
template <class In, class N>
  requires detail::shift_count<N>
[[nodiscard]] constexpr auto SHR(const In& in, const N& n) {
  static_assert(sizeof(detail::shift_operand_check<In>) > 0);
  return detail::shifted<detail::shift_direction::right>(in, n);
}

/// ROL(IN, N): IN rotated left by N bits, modulo the width (ROL of a BYTE by 9 is ROL by 1; a
/// negative N rotates right).
template <class In, class N>
  requires detail::shift_count<N>
[[nodiscard]] constexpr auto ROL(const In& in, const N& n) {
  static_assert(sizeof(detail::shift_operand_check<In>) > 0);
  return detail::rotated<detail::shift_direction::left>(in, n);
}

/// ROR(IN, N): IN rotated right by N bits, modulo the width (a negative N rotates left).
template <class In, class N>
  requires detail::shift_count<N>
[[nodiscard]] constexpr auto ROR(const In& in, const N& n) {
  static_assert(sizeof(detail::shift_operand_check<In>) > 0);
  return detail::rotated<detail::shift_direction::right>(in, n);
}

namespace detail {

/// AND/OR/XOR's inputs: BOOL or bit strings (IEC's ANY_BIT), with integers as CODESYS allows
/// for the operators.
template <class X>
concept bitwise_operand = std::is_same_v<argument_t<X>, BOOL> || int_value<argument_t<X>> ||
                          cpp_integer<std::remove_cvref_t<X>> || std::is_same_v<std::remove_cvref_t<X>, bool>;

}  // namespace detail

/// AND(IN1, IN2, ...): the bitwise AND of two or more inputs (BOOL: all TRUE), as `&`.
template <class In1, class In2, class... More>
  requires(detail::bitwise_operand<In1> && detail::bitwise_operand<In2> && (detail::bitwise_operand<More> && ...))
[[nodiscard]] constexpr auto AND(In1&& in1, In2&& in2, More&&... more) {
  using C = detail::common_argument_t<In1, In2, More...>;
  static_assert(sizeof(detail::arguments_check<In1, In2, More...>) > 0);  // reports inputs that do not meet
  return static_cast<C>(((detail::as_common<C>(std::forward<In1>(in1)) & detail::as_common<C>(std::forward<In2>(in2))) &
                         ... & detail::as_common<C>(std::forward<More>(more))));
}

/// OR(IN1, IN2, ...): the bitwise OR of two or more inputs, as `|`.
template <class In1, class In2, class... More>
  requires(detail::bitwise_operand<In1> && detail::bitwise_operand<In2> && (detail::bitwise_operand<More> && ...))
[[nodiscard]] constexpr auto OR(In1&& in1, In2&& in2, More&&... more) {
  using C = detail::common_argument_t<In1, In2, More...>;
  static_assert(sizeof(detail::arguments_check<In1, In2, More...>) > 0);  // reports inputs that do not meet
  return static_cast<C>(((detail::as_common<C>(std::forward<In1>(in1)) | detail::as_common<C>(std::forward<In2>(in2))) |
                         ... | detail::as_common<C>(std::forward<More>(more))));
}

/// XOR(IN1, IN2, ...): the bitwise exclusive OR of two or more inputs, as `^` (BOOL: TRUE if an
/// odd number of inputs is TRUE, IEC's extensible XOR).
template <class In1, class In2, class... More>
  requires(detail::bitwise_operand<In1> && detail::bitwise_operand<In2> && (detail::bitwise_operand<More> && ...))
[[nodiscard]] constexpr auto XOR(In1&& in1, In2&& in2, More&&... more) {
  using C = detail::common_argument_t<In1, In2, More...>;
  static_assert(sizeof(detail::arguments_check<In1, In2, More...>) > 0);  // reports inputs that do not meet
  return static_cast<C>(((detail::as_common<C>(std::forward<In1>(in1)) ^ detail::as_common<C>(std::forward<In2>(in2))) ^
                         ... ^ detail::as_common<C>(std::forward<More>(more))));
}

/// NOT(IN): the bitwise complement in IN's width (BOOL: the negation), as `~`.
template <class In>
  requires(detail::iec_argument<In> && detail::bitwise_operand<In>)
[[nodiscard]] constexpr auto NOT(const In& in) {
  using T = detail::nominal_t<detail::argument_t<In>>;
  return T(~T(detail::argument_value(in)));
}

}  // namespace iecoop

#include <iecoop/detail/pop_macros.hpp>
