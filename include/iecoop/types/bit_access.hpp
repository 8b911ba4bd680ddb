// SPDX-License-Identifier: MIT
// iecoop/types/bit_access.hpp — ST's bit access `x.3`: bit<3>(x), read and written.
//
//     IF wStatus.3 THEN                 if (bit<3>(wStatus)) {
//     wStatus.15 := bReady;             bit<15>(wStatus) = bReady;
//     bOdd := diCount.0;                bOdd = bit<0>(diCount);
//     fbDrive.wControl.7 := TRUE;       bit<7>(fbDrive.wControl) = TRUE;
//
// As in ST the bit number is a constant, checked against the type's width while compiling
// (WORD: 0..15), and bit 0 is the least significant. It works on every integer and bit-string
// type (CODESYS allows both) and on any variable of one — a block's var<> or VAR_OUTPUT, an
// in-out, a located %Q variable, a RETAIN variable: writing a bit assigns the whole variable
// with that bit changed, as ST does, so a read-only variable rejects it as it rejects any
// assignment. A bit is a BOOL in expressions, conditions and calls.
#pragma once

#include <cstddef>
#include <type_traits>

#include <iecoop/config.hpp>
#include <iecoop/types/detail/value_operators.hpp>
#include <iecoop/types/elementary.hpp>

#include <iecoop/detail/push_macros.hpp>

namespace iecoop {

namespace detail {

/// The checks of bit<N>(x), as a class: instantiated where the call is compiled, so that a
/// misuse is reported first. `rep` is the C++ integer of x's type.
template <std::size_t N, class X>
struct bit_number_check {
  using T = unwrapped_t<X>;
  static_assert(is_integer<T>::value,
                "iecoop: bit<N>(x) is ST's x.N, for integers and bit strings (BYTE, WORD, INT, ...); a BOOL is "
                "one bit already");
  using rep = typename std::conditional_t<is_integer<T>::value, T, WORD>::rep;
  static_assert(!is_integer<T>::value || N < sizeof(rep) * 8,
                "iecoop: bit<N>(x): N counts from 0 (the least significant bit) to the width less one: "
                "BYTE 0..7, WORD 0..15, DWORD 0..31, LWORD 0..63");
  static constexpr rep mask = N < sizeof(rep) * 8 ? static_cast<rep>(rep{1} << N) : rep{0};
};

}  // namespace detail

/**
 * Bit N of the variable `x`, as ST's `x.N`: reads as a BOOL, and assigning a BOOL to it sets
 * or clears that bit of x. Made by bit<N>(x); it refers to x, so use it within the statement,
 * as ST does.
 */
template <std::size_t N, class X>
class bit_reference : public detail::condition_conversion<bit_reference<N, X>, BOOL> {
  using check = detail::bit_number_check<N, X>;
  using T = detail::unwrapped_t<X>;
  using Rep = typename check::rep;
  static constexpr Rep mask = check::mask;

 public:
  using value_type = BOOL;
  using iecoop_value_wrapper = void;  // in expressions, its value (detail/value_operators.hpp)

  constexpr explicit bit_reference(X& x) noexcept : x_(x) {}

  /// The bit, as a BOOL.
  [[nodiscard]] constexpr BOOL get() const { return BOOL((T(detail::value_of(x_)).value() & mask) != 0); }

  /// `x.N := b;`: x with bit N set to b.
  constexpr const bit_reference& operator=(BOOL b) const {
    const Rep v = T(detail::value_of(x_)).value();
    x_ = T(static_cast<Rep>(static_cast<bool>(b) ? v | mask : v & static_cast<Rep>(~mask)));
    return *this;
  }
  /// `x.N := y.M;`: the other bit's value.
  constexpr const bit_reference& operator=(const bit_reference& other) const { return *this = other.get(); }
  template <std::size_t M, class Y>
  constexpr const bit_reference& operator=(const bit_reference<M, Y>& other) const {
    return *this = other.get();
  }

  bit_reference(const bit_reference&) = default;

 private:
  X& x_;
};

/// `x.N` of a variable: bit N, to read or to assign.
template <std::size_t N, class X>
  requires(!std::is_const_v<X>)
[[nodiscard]] constexpr bit_reference<N, X> bit(X& x) noexcept {
  return bit_reference<N, X>(x);
}

/// `x.N` of a constant or a value: bit N, as a BOOL.
template <std::size_t N, class X>
[[nodiscard]] constexpr auto bit(const X& x) {
  using check = detail::bit_number_check<N, X>;
  static_assert(sizeof(check) > 0);  // its static_asserts report misuse
  if constexpr (detail::is_integer<detail::unwrapped_t<X>>::value) {
    using T = detail::unwrapped_t<X>;
    return BOOL((T(detail::value_of(x)).value() & check::mask) != 0);
  } else {
    return FALSE;
  }
}

}  // namespace iecoop

#include <iecoop/detail/pop_macros.hpp>
