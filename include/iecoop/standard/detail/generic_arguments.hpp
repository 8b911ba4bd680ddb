// SPDX-License-Identifier: MIT
// iecoop/standard/detail/generic_arguments.hpp — the arguments of IEC's generic (overloaded) standard
// functions: MAX(a, b, c), LIMIT(mn, x, mx), MUX(k, ...), ADD(a, b, ...), GT(a, b, c).
//
// IEC gives all inputs of such a function one type, the type every input converts to
// implicitly; ST's `a + b` already computes it (INT and DINT meet as DINT, INT and REAL as REAL,
// REAL and LREAL as LREAL), so the functions use the same rule, with the same diagnostics for
// types that do not meet. Not for direct inclusion.
//
// - A variable wrapper (var<INT>, retain<>, an in-out, a located variable, a property, a
//   subrange, a var<> of a subrange) passes its value: argument_t and argument_value
//   (detail/value_operators.hpp) unwrap it.
// - An intermediate result keeps its register: MAX(i + 1, j) is an intermediate<INT> that still
//   holds 32768 for i = 32767, as `i + 1 > j` sees it.
// - A C++ number (`MAX(iSpeed, 100)`) takes the type of the IEC arguments; a C++ integer is no
//   longer a constant inside the function, so it is checked at run time as a call's argument
//   is: out of range it reports fault_kind::invalid_value and keeps the low bytes.
#pragma once

#include <concepts>
#include <cstddef>
#include <type_traits>
#include <utility>

#include <iecoop/fault.hpp>
#include <iecoop/types/date_time.hpp>
#include <iecoop/types/detail/value_operators.hpp>
#include <iecoop/types/elementary.hpp>
#include <iecoop/types/enumeration.hpp>
#include <iecoop/types/string.hpp>
#include <iecoop/types/time.hpp>

#include <iecoop/detail/push_macros.hpp>

namespace iecoop::detail {

/// An argument of an IEC type (a value, an intermediate result, an enumeration's component, or
/// a variable of one).
template <class X>
concept iec_argument = is_iec_value<argument_t<X>>::value || Enumeration<argument_t<X>>;

/// A C++ number given to a generic function (`100`, `2.5`), which takes the IEC arguments' type.
template <class X>
concept cpp_number_argument = (cpp_integer<std::remove_cvref_t<X>> || std::floating_point<std::remove_cvref_t<X>>);

// --- The common type of two IEC types ---------------------------------------------------

template <class A, class B>
struct common_iec {};

/// The IEC type of a sum: REAL + REAL computes in float, the REAL type of that float.
template <class T>
struct iec_sum {
  using type = T;
};
template <std::floating_point F>
struct iec_sum<F> {
  using type = real<F>;
};

// Numbers: the type of `a + b`, kept as an intermediate only where an operand is one. (`a + b`
// of a WORD and an INT, or of a DINT and a REAL, has a type too and reports the mismatch only
// where it is evaluated: those pairs are excluded here, and arguments_check reports them.)
template <class A, class B>
  requires((int_value<A> || is_real<A>::value) && (int_value<B> || is_real<B>::value) && !unrelated_integers<A, B> &&
           !inexact_real_mix<A, B>)
struct common_iec<A, B> {
  using raw = decltype(std::declval<const A&>() + std::declval<const B&>());
  using sum = typename iec_sum<raw>::type;
  using type =
      std::conditional_t<is_intermediate<sum>::value && !is_intermediate<A>::value && !is_intermediate<B>::value,
                         nominal_t<sum>, sum>;
};

template <>
struct common_iec<BOOL, BOOL> {
  using type = BOOL;
};

// Components of one enumeration (SEL, MUX, EQ, NE, and the ordering functions as C++ orders
// them); an enumeration does not meet another type, not even its base type.
template <Enumeration E>
struct common_iec<E, E> {
  using type = E;
};

// TIME and LTIME meet as LTIME, as in ST.
template <class A, class B>
  requires(is_time<A>::value && is_time<B>::value)
struct common_iec<A, B> {
  using type = std::conditional_t<(sizeof(A) >= sizeof(B)), A, B>;
};

// Points in time of one kind (DATE and LDATE, TOD and LTOD, DT and LDT) meet as the L form
// where one of them is, as in ST.
template <class A, class B>
  requires(is_time_point<A>::value && is_time_point<B>::value && A::kind == B::kind)
struct common_iec<A, B> {
  using type = std::conditional_t<(sizeof(A) >= sizeof(B)), A, B>;
};

// Strings of one character type: the larger capacity.
template <class C, std::size_t N, std::size_t M>
struct common_iec<iec_string<C, N>, iec_string<C, M>> {
  using type = iec_string<C, (N >= M ? N : M)>;
};

template <class A, class B>
concept have_common_iec = requires { typename common_iec<A, B>::type; };

/// The diagnostic for two argument types of a generic function that do not meet.
template <class Left, class Right>
constexpr void no_common_argument_type() {
  static_assert(dependent_false<Left, Right>,
                "iecoop: the inputs of this generic standard function have types (spelled in `Left` and `Right`) "
                "that IEC does not convert to one type; convert one input explicitly, e.g. INT_TO_REAL(i)");
}

// --- The common type of a list of arguments ---------------------------------------------

template <class Common, class X>
struct next_common {
  using type = Common;  // a C++ number, or a type that does not meet (arguments_check reports it)
};
template <class X>
  requires iec_argument<X>
struct next_common<void, X> {
  using type = argument_t<X>;
};
template <class Common, class X>
  requires(iec_argument<X> && have_common_iec<Common, argument_t<X>>)
struct next_common<Common, X> {
  using type = typename common_iec<Common, argument_t<X>>::type;
};

template <class Common, class... X>
struct fold_common {
  using type = Common;
};
template <class Common, class X, class... Rest>
struct fold_common<Common, X, Rest...> {
  using type = typename fold_common<typename next_common<Common, X>::type, Rest...>::type;
};

/// The first IEC argument type that does not meet the types before it, as the pair
/// `mismatch_pair<Before, It>`, or void.
template <class Before, class It>
struct mismatch_pair {};
template <class Common, class... X>
struct first_mismatch {
  using type = void;
};
template <class Common, class X, class... Rest>
struct first_mismatch<Common, X, Rest...> {
  using type = std::conditional_t<iec_argument<X> && !std::is_void_v<Common> && !have_common_iec<Common, argument_t<X>>,
                                  mismatch_pair<Common, argument_t<X>>,
                                  typename first_mismatch<typename next_common<Common, X>::type, Rest...>::type>;
};

template <class Mismatch>
struct report_mismatch {};
template <class Before, class It>
struct report_mismatch<mismatch_pair<Before, It>> {
  static_assert((no_common_argument_type<spelled_iec_name_t<nominal_t<Before>>, spelled_iec_name_t<nominal_t<It>>>(),
                 true));
};

/// A complete type whose instantiation reports inputs that do not meet. Each generic function
/// starts with `static_assert(sizeof(detail::arguments_check<X...>) > 0);`, which instantiates
/// it where the call is compiled, so that a mismatch is reported first.
template <class... X>
using arguments_check = report_mismatch<typename first_mismatch<void, X...>::type>;

/// The type all arguments X... take: the common type of the IEC ones, or, where every argument
/// is a C++ number, their C++ common type.
template <class... X>
using common_argument_t =
    typename std::conditional_t<std::is_void_v<typename fold_common<void, X...>::type>,
                                std::common_type<std::remove_cvref_t<X>...>, fold_common<void, X...>>::type;

/// An argument as a value of the common type C.
template <class C, class X>
constexpr C as_common(X&& x) {
  if constexpr (int_value<argument_t<X>> && is_intermediate<C>::value) {
    // Register to register: an intermediate of a narrower type keeps its whole value.
    return C::from_register(in_register<nominal_t<C>>(argument_value(std::forward<X>(x))));
  } else if constexpr (iec_argument<X> && requires { static_cast<C>(argument_value(std::forward<X>(x))); }) {
    return static_cast<C>(argument_value(std::forward<X>(x)));
  } else if constexpr (iec_argument<X>) {
    return C{};  // a type that does not meet the others: arguments_check has reported it
  } else if constexpr (is_iec_string<C>::value && std::is_constructible_v<C, X>) {
    return C(std::forward<X>(x));  // a string literal among STRINGs
  } else if constexpr (std::is_same_v<std::remove_cvref_t<X>, bool> && std::is_same_v<C, BOOL>) {
    return BOOL(x);
  } else if constexpr (cpp_integer<std::remove_cvref_t<X>> && (int_value<C>)) {
    using rep = typename nominal_t<C>::rep;
    if (!std::in_range<rep>(x)) {
      fault(fault_kind::invalid_value,
            "a C++ integer given to a standard function is out of range for the other inputs' IEC type; the low "
            "bytes are kept");
    }
    return C(nominal_t<C>(static_cast<rep>(x)));
  } else if constexpr (cpp_number_argument<X> && is_real<C>::value) {
    return C(static_cast<typename real_side<C>::type>(x));
  } else if constexpr (cpp_number_argument<X> && std::is_arithmetic_v<C>) {
    return static_cast<C>(x);
  } else {
    static_assert(dependent_false<X, C>,
                  "iecoop: a C++ value given to a standard function must be a number that the other inputs' IEC "
                  "type takes (an integer for ANY_INT, a number for ANY_REAL); write an IEC value instead, e.g. "
                  "T#5s for a TIME");
    return C{};
  }
}

}  // namespace iecoop::detail

#include <iecoop/detail/pop_macros.hpp>
