// SPDX-License-Identifier: MIT
// iecoop/types/subrange.hpp — subrange types: ST's `x : INT(0..100);` is subrange<INT, 0, 100>,
// `TYPE T_Percent : INT(0..100); END_TYPE` is `using T_Percent = subrange<INT, 0, 100>;`.
//
// A constant outside the range does not compile, as in CODESYS. A run-time value outside it
// is a fault (fault_kind::out_of_range), after which the nearest limit is stored — what the
// implementation CODESYS proposes for its implicit CheckRangeSigned/CheckRangeUnsigned does.
// The check sees the whole value of an expression, before it is narrowed to the base type:
// `i := 10 * y` with y = 1000 stores the upper limit, not 10000 cut to 16 bits.
#pragma once

#include <type_traits>
#include <utility>

#include <iecoop/config.hpp>
#include <iecoop/detail/diagnostics.hpp>
#include <iecoop/detail/iec_value.hpp>
#include <iecoop/fault.hpp>
#include <iecoop/types/detail/value_operators.hpp>
#include <iecoop/types/elementary.hpp>

#include <iecoop/detail/push_macros.hpp>

namespace iecoop {

namespace detail {

/// CODESYS's CheckRangeSigned/CheckRangeUnsigned: reports a value outside a subrange (the
/// caller then stores the nearest limit).
inline void out_of_subrange() {
  fault(fault_kind::out_of_range, "value outside its subrange type; the nearest limit is stored");
}

}  // namespace detail

/**
 * A variable of the subrange `Lower..Upper` of the IEC integer type `Base` (ST:
 * `Base(Lower..Upper)`). It reads as a Base in every expression; every assignment is checked.
 *
 *     subrange<INT, 0, 100> iPercent;        // iPercent : INT(0..100);
 *     iPercent = 50;                         // a constant: checked at compile time
 *     iPercent = iRaw * 10;                  // checked when it runs: above 100, a fault and 100
 *     INT i = iPercent + 1;                  // reads as an INT
 *
 * It starts at 0 where 0 is in the range (CODESYS's memory starts at zero) and at the lower
 * limit otherwise (IEC's rule, which keeps every value of the type in its range).
 */
template <class Base, auto Lower, auto Upper>
class subrange {
  static_assert(detail::is_integer<Base>::value,
                "iecoop: a subrange's base type is an IEC integer (SINT..ULINT, BYTE..LWORD); INT(0..100) is "
                "subrange<INT, 0, 100>");
  static_assert(detail::cpp_integer<decltype(Lower)> && detail::cpp_integer<decltype(Upper)>,
                "iecoop: a subrange's limits are integer constants; write subrange<INT, 0, 100>");

  using rep = typename Base::rep;

 public:
  using value_type = Base;
  using iecoop_value_wrapper = void;
  using iecoop_subrange = void;

  static_assert(std::in_range<rep>(Lower) && std::in_range<rep>(Upper),
                "iecoop: a subrange's limits are values of its base type");
  static_assert(std::cmp_less_equal(Lower, Upper), "iecoop: a subrange's lower limit must not exceed its upper limit");

  /// The lower limit.
  static constexpr Base lower = Base(static_cast<rep>(Lower));
  /// The upper limit.
  static constexpr Base upper = Base(static_cast<rep>(Upper));

  constexpr subrange() noexcept = default;

  /// A constant, checked at compile time (`iPercent = 50;`, `subrange<INT, 0, 100> x = 5;`).
  template <detail::cpp_integer C>
  consteval subrange(C constant) : value_(static_cast<rep>(constant)) {  // implicit: as INT x = 5
    if (!std::in_range<rep>(constant) || std::cmp_less(constant, Lower) || std::cmp_greater(constant, Upper)) {
      // clang-format off
      detail::compile_error("iecoop: constant outside the subrange; assign a value between the subrange's limits");
      // clang-format on
    }
  }
  /// A value of the base type, an IEC integer that widens into it implicitly, or an
  /// intermediate result: checked when it runs.
  template <class V>
    requires(detail::int_value<V> && std::is_convertible_v<const V&, Base>)
  constexpr subrange(const V& value) : value_(checked(value)) {}  // implicit: as an assignment
  constexpr subrange(const subrange&) noexcept = default;

  constexpr subrange& operator=(const subrange&) noexcept = default;
  /// `x := expression;` with CheckRange.
  template <class V>
    requires(detail::int_value<V> && std::is_convertible_v<const V&, Base>)
  constexpr subrange& operator=(const V& value) {
    value_ = checked(value);
    return *this;
  }
  /// A value of another subrange type: checked as any value of its base type.
  template <class B, auto L, auto U>
    requires std::is_convertible_v<const B&, Base>
  constexpr subrange& operator=(const subrange<B, L, U>& other) {
    value_ = checked(other.get());
    return *this;
  }
  /// A C++ integer known only when it runs (a call's argument, for example): checked then.
  template <detail::cpp_integer C>
  constexpr void assign_checked(C value) {
    value_ = checked_wide(value);
  }

  /// The value, as its base type.
  [[nodiscard]] constexpr Base get() const noexcept { return value_; }
  constexpr operator Base() const noexcept { return value_; }  // implicit: reads as its base type
  /// Reads as any IEC type its base type widens into (a DINT from an INT subrange).
  template <class U>
    requires(detail::is_integer<U>::value && !std::is_same_v<U, Base> && std::is_convertible_v<Base, U>)
  constexpr operator U() const noexcept {  // implicit: as its base type would
    return U(value_);
  }
  /// The value as its C++ integer.
  [[nodiscard]] constexpr rep value() const noexcept { return value_.value(); }

 private:
  static constexpr Base initial() noexcept {
    if (std::cmp_less_equal(Lower, 0) && std::cmp_greater_equal(Upper, 0)) return Base{};
    return lower;
  }

  template <class C>
  static constexpr Base checked_wide(C v) {
    if (std::cmp_less(v, Lower)) [[unlikely]] {
      detail::out_of_subrange();
      return lower;
    }
    if (std::cmp_greater(v, Upper)) [[unlikely]] {
      detail::out_of_subrange();
      return upper;
    }
    return Base(static_cast<rep>(v));
  }
  template <class V>
  static constexpr Base checked(const V& value) {
    // An intermediate result is checked with its whole register value, before narrowing.
    return checked_wide(value.value());
  }

  Base value_ = initial();
};

template <class Base, auto Lower, auto Upper>
struct detail::is_iec_value<subrange<Base, Lower, Upper>> : std::true_type {};

}  // namespace iecoop

#include <iecoop/detail/pop_macros.hpp>
