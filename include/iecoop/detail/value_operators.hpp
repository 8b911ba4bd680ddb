// SPDX-License-Identifier: MIT
// iecoop/detail/value_operators.hpp — the operators of iecoop's variable wrappers (var<>,
// in_out<>, output<>, property<>): in an expression a wrapper is its value.
// IWYU pragma: private, include <iecoop/iecoop.hpp>
//
// A wrapper converts to its value implicitly, but C++ applies only one user-defined
// conversion, and not at all to operators that are templates: `rVar * 2.0` (REAL converts
// to float, a second conversion) or `sText == 'abc'` would not compile. These operators
// unwrap the operands first and then use the value's own operators, so exactly the
// expressions that work on T work on a wrapper of T.
#pragma once

#include <type_traits>
#include <utility>

#include <iecoop/types.hpp>

namespace iecoop::detail {

/// A variable wrapper: a type that declares `using iecoop_value_wrapper = void;` and whose
/// `get()` is its value. (A type may declare it as something else to opt out, as a property
/// readable only by its block does.)
template <class X>
concept value_wrapper = std::is_void_v<typename std::remove_cvref_t<X>::iecoop_value_wrapper>;

/// An operand's value: a wrapper's get(), anything else itself. The operand keeps its
/// constness, so a property read through a non-const block calls its Get on that block.
template <class X>
constexpr decltype(auto) value_of(X&& x) {
  if constexpr (value_wrapper<X>) {
    return std::forward<X>(x).get();
  } else {
    return std::forward<X>(x);
  }
}

template <class X>
using unwrapped_t = std::remove_cvref_t<decltype(value_of(std::declval<X>()))>;

template <class A, class B>
concept wrapper_operands = value_wrapper<A> || value_wrapper<B>;

// A wrapped integer with a C++ number (`count + 1`) is left to the integer's own operators,
// which check the constant while compiling (the wrapper converts to the integer for them).
template <class X, class Y>
concept wrapped_integer_with_number =
    value_wrapper<X> && AnyInteger<unwrapped_t<X>> && std::is_arithmetic_v<std::remove_cvref_t<Y>>;
template <class A, class B>
concept wrapper_arithmetic =
    wrapper_operands<A, B> && !wrapped_integer_with_number<A, B> && !wrapped_integer_with_number<B, A>;

// enable_if rather than requires: Clang 14 substitutes into the return type before checking
// a requires-clause, and would recurse for unrelated operands.
template <bool Enable>
using enable_for = std::enable_if_t<Enable, int>;

}  // namespace iecoop::detail

namespace iecoop {

template <class A, class B, detail::enable_for<detail::wrapper_arithmetic<A, B>> = 0>
constexpr auto operator+(A&& a, B&& b)
    -> decltype(detail::value_of(std::forward<A>(a)) + detail::value_of(std::forward<B>(b))) {
  return detail::value_of(std::forward<A>(a)) + detail::value_of(std::forward<B>(b));
}
template <class A, class B, detail::enable_for<detail::wrapper_arithmetic<A, B>> = 0>
constexpr auto operator-(A&& a, B&& b)
    -> decltype(detail::value_of(std::forward<A>(a)) - detail::value_of(std::forward<B>(b))) {
  return detail::value_of(std::forward<A>(a)) - detail::value_of(std::forward<B>(b));
}
template <class A, class B, detail::enable_for<detail::wrapper_arithmetic<A, B>> = 0>
constexpr auto operator*(A&& a, B&& b)
    -> decltype(detail::value_of(std::forward<A>(a)) * detail::value_of(std::forward<B>(b))) {
  return detail::value_of(std::forward<A>(a)) * detail::value_of(std::forward<B>(b));
}
template <class A, class B, detail::enable_for<detail::wrapper_arithmetic<A, B>> = 0>
constexpr auto operator/(A&& a, B&& b)
    -> decltype(detail::value_of(std::forward<A>(a)) / detail::value_of(std::forward<B>(b))) {
  return detail::value_of(std::forward<A>(a)) / detail::value_of(std::forward<B>(b));
}
template <class A, class B, detail::enable_for<detail::wrapper_arithmetic<A, B>> = 0>
constexpr auto operator%(A&& a, B&& b)
    -> decltype(detail::value_of(std::forward<A>(a)) % detail::value_of(std::forward<B>(b))) {
  return detail::value_of(std::forward<A>(a)) % detail::value_of(std::forward<B>(b));
}
template <class A, class B, detail::enable_for<detail::wrapper_arithmetic<A, B>> = 0>
constexpr auto operator&(A&& a, B&& b)
    -> decltype(detail::value_of(std::forward<A>(a)) & detail::value_of(std::forward<B>(b))) {
  return detail::value_of(std::forward<A>(a)) & detail::value_of(std::forward<B>(b));
}
template <class A, class B, detail::enable_for<detail::wrapper_arithmetic<A, B>> = 0>
constexpr auto operator|(A&& a, B&& b)
    -> decltype(detail::value_of(std::forward<A>(a)) | detail::value_of(std::forward<B>(b))) {
  return detail::value_of(std::forward<A>(a)) | detail::value_of(std::forward<B>(b));
}
template <class A, class B, detail::enable_for<detail::wrapper_arithmetic<A, B>> = 0>
constexpr auto operator^(A&& a, B&& b)
    -> decltype(detail::value_of(std::forward<A>(a)) ^ detail::value_of(std::forward<B>(b))) {
  return detail::value_of(std::forward<A>(a)) ^ detail::value_of(std::forward<B>(b));
}
template <class A, class B, detail::enable_for<detail::wrapper_operands<A, B>> = 0>
constexpr auto operator==(A&& a, B&& b)
    -> decltype(detail::value_of(std::forward<A>(a)) == detail::value_of(std::forward<B>(b))) {
  return detail::value_of(std::forward<A>(a)) == detail::value_of(std::forward<B>(b));
}
template <class A, class B, detail::enable_for<detail::wrapper_operands<A, B>> = 0>
constexpr auto operator<=>(A&& a, B&& b)
    -> decltype(detail::value_of(std::forward<A>(a)) <=> detail::value_of(std::forward<B>(b))) {
  return detail::value_of(std::forward<A>(a)) <=> detail::value_of(std::forward<B>(b));
}
template <class A, detail::enable_for<detail::value_wrapper<A>> = 0>
constexpr auto operator-(A&& a) -> decltype(-detail::value_of(std::forward<A>(a))) {
  return -detail::value_of(std::forward<A>(a));
}
template <class A, detail::enable_for<detail::value_wrapper<A>> = 0>
constexpr auto operator!(A&& a) -> decltype(!detail::value_of(std::forward<A>(a))) {
  return !detail::value_of(std::forward<A>(a));
}
template <class A, detail::enable_for<detail::value_wrapper<A>> = 0>
constexpr auto operator~(A&& a) -> decltype(~detail::value_of(std::forward<A>(a))) {
  return ~detail::value_of(std::forward<A>(a));
}

}  // namespace iecoop
