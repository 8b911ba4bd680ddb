// SPDX-License-Identifier: MIT
// iecoop/pou/named_arguments.hpp — named parameters, ST's `IN := x` and `Q => y`, for calls of function
// blocks, programs, methods and functions: "IN"_ = x and "Q"_ >> y.
//
//     CMD_TMR("IN"_ = start, "PT"_ = "T#300ms"_iec);          // ST: CMD_TMR(IN := start, PT := T#300ms);
//     fb.DoIt({"sInput_3"_ = "Hello", "iInput_1"_ = 16});      // ST: fb.DoIt(sInput_3 := 'Hello', iInput_1 := 16);
//     PRG_Sum("a"_ = 1, "b"_ = 2, "sum"_ >> result);          // ST: PRG_Sum(a := 1, b := 2, sum => result);
//
// The names are checked at compile time against the callee's declared variables.
#pragma once

#include <cstddef>
#include <string_view>
#include <type_traits>
#include <utility>

#include <iecoop/config.hpp>
#include <iecoop/detail/fixed_string.hpp>
#include <iecoop/detail/scalar_access.hpp>
#include <iecoop/fault.hpp>
#include <iecoop/types/detail/value_operators.hpp>
#include <iecoop/types/elementary.hpp>
#include <iecoop/types/time.hpp>

#include <iecoop/detail/push_macros.hpp>

namespace iecoop {

template <detail::fixed_string Name, class V>
struct named_input;
template <detail::fixed_string Name, class T>
struct named_output;

/// A parameter name, written "IN"_. `"IN"_ = x` is ST's `IN := x` (an input, or the
/// variable bound to a VAR_IN_OUT); `"Q"_ >> y` is ST's `Q => y` (y receives the output
/// after the call).
template <detail::fixed_string Name>
struct param_name {
  static constexpr std::string_view name{Name.chars, Name.size};

  template <class V>
  constexpr named_input<Name, V> operator=(V&& value) const noexcept {  // implicit: ST's :=
    return named_input<Name, V>{std::forward<V>(value)};
  }
  template <class T>
  constexpr named_output<Name, T> operator>>(T& target) const noexcept {  // ST's =>
    return named_output<Name, T>{&target};
  }
};

/// `Name := value`. An lvalue is kept by reference (so a VAR_IN_OUT can bind to it), an
/// rvalue by value.
template <detail::fixed_string Name, class V>
struct named_input {
  static constexpr std::string_view name{Name.chars, Name.size};
  static constexpr auto spelling = Name;  ///< the name as a template argument (diagnostics)
  V value;
};

/// `Name => *target`.
template <detail::fixed_string Name, class T>
struct named_output {
  static constexpr std::string_view name{Name.chars, Name.size};
  static constexpr auto spelling = Name;  ///< the name as a template argument (diagnostics)
  using target_type = T;
  T* target;
};

namespace detail {
template <class T>
struct is_named_input : std::false_type {};
template <fixed_string N, class V>
struct is_named_input<named_input<N, V>> : std::true_type {};
template <class T>
struct is_named_output : std::false_type {};
template <fixed_string N, class T>
struct is_named_output<named_output<N, T>> : std::true_type {};
}  // namespace detail

namespace detail {
template <class A>
constexpr std::string_view name_of_argument() noexcept {
  if constexpr (is_named_input<std::remove_cvref_t<A>>::value || is_named_output<std::remove_cvref_t<A>>::value) {
    return std::remove_cvref_t<A>::name;
  } else {
    return {};
  }
}
// Positional arguments come first, named ones after them.
template <class... A>
constexpr bool positional_first() noexcept {
  constexpr bool named[] = {
      false, (is_named_input<std::remove_cvref_t<A>>::value || is_named_output<std::remove_cvref_t<A>>::value)...};
  for (std::size_t i = 2; i < sizeof...(A) + 1; ++i) {
    if (named[i - 1] && !named[i]) return false;
  }
  return true;
}

/// No two named arguments of a call name the same parameter (ST rejects that too).
template <class... A>
constexpr bool distinct_names() noexcept {
  constexpr std::string_view names[] = {std::string_view{}, name_of_argument<A>()...};
  for (std::size_t i = 1; i < sizeof...(A) + 1; ++i) {
    for (std::size_t j = i + 1; j < sizeof...(A) + 1; ++j) {
      if (!names[i].empty() && names[i] == names[j]) return false;
    }
  }
  return true;
}
}  // namespace detail

/// `"x"_ = value`
template <class T>
concept NamedInput = detail::is_named_input<std::remove_cvref_t<T>>::value;
/// `"x"_ >> variable`
template <class T>
concept NamedOutput = detail::is_named_output<std::remove_cvref_t<T>>::value;
/// Either kind of named parameter.
template <class T>
concept NamedArgument = NamedInput<T> || NamedOutput<T>;

inline namespace literals {
/// A parameter name: "IN"_ (see param_name). (constexpr, not consteval: Clang 14 leaves a
/// consteval literal operator template used inside a function template undefined.)
template <detail::fixed_string Name>
constexpr param_name<Name> operator""_() noexcept {
  return {};
}
}  // namespace literals

namespace detail {

/// A C++ integer arriving at an IEC integer or duration through a call's argument list: the
/// value is no longer a constant there, so its range is checked at run time instead.
template <class Target, class V>
concept checked_integer_argument =
    cpp_integer<std::remove_cvref_t<V>> &&
    (AnyInteger<Target> || AnyDuration<Target>)&&!range_within<std::remove_cvref_t<V>, typename Target::rep>;

}  // namespace detail

namespace detail {

/// An argument of type V is accepted for a parameter of type Target, as ST's implicit
/// conversions allow (a wrapper passes its value; a C++ integer is checked at run time).
template <class Target, class V>
constexpr bool argument_accepted() noexcept {
  if constexpr (value_wrapper<V> && !value_wrapper<Target>) {
    return argument_accepted<Target, decltype(value_of(std::declval<V>()))>();
  } else if constexpr (checked_integer_argument<Target, V>) {
    return true;
  } else if constexpr (value_wrapper<Target>) {
    return std::is_assignable_v<Target&, V>;
  } else {
    return std::is_convertible_v<V, Target>;
  }
}

/// The value type an argument of type V passes (a wrapper's value, else V itself).
template <class V>
using passed_t = std::remove_cvref_t<decltype(value_of(std::declval<V>()))>;

/// Why an argument of type V is not accepted for a Target: the conversion to write, when both
/// are IEC types; otherwise the rule.
template <class Target, class V>
constexpr void report_argument_type() {
  using from = nominal_t<passed_t<V>>;
  using to = std::remove_cvref_t<decltype(value_of(std::declval<Target&>()))>;
  if constexpr (!iec_name<from>::value.empty() && !iec_name<to>::value.empty()) {
    no_implicit_conversion<spelled_iec_name_t<from>, spelled_iec_name_t<to>>();
  } else {
    static_assert(dependent_false<V>,
                  "iecoop: the argument's type does not convert to the parameter's type; convert it explicitly "
                  "(e.g. DINT_TO_INT(x)) or pass a value of the parameter's type");
  }
}

}  // namespace detail

/**
 * Stores an argument of a call in the variable `target`, following the rules of assignment:
 * IEC values convert as ST allows implicitly (a DINT does not go into an INT), and a C++
 * integer that may not fit (an `int` into an INT) is range-checked at run time, since a
 * constant passed through a call is no longer a constant: out of range, it reports
 * fault_kind::invalid_value and keeps the low bytes.
 */
template <class Target, class V>
constexpr void assign_argument(Target& target, V&& value) {
  if constexpr (detail::value_wrapper<V> && !detail::value_wrapper<Target>) {
    // A variable wrapper (a block's var<>, a retain<>, ...) passes its value, which converts
    // as a plain variable of its type would (a var<INT> into a DINT input).
    assign_argument(target, detail::value_of(std::forward<V>(value)));
  } else if constexpr (requires { typename Target::iecoop_subrange; } && detail::cpp_integer<std::remove_cvref_t<V>>) {
    target.assign_checked(value);  // a subrange's CheckRange, when it runs
  } else if constexpr (detail::checked_integer_argument<Target, V>) {
    using rep = typename Target::rep;
    if (!std::in_range<rep>(value)) {
      fault(fault_kind::invalid_value, "argument out of range for the parameter's IEC type; the low bytes are kept");
    }
    if constexpr (AnyDuration<Target>) {
      detail::copy_value(target, Target::from_ticks(static_cast<rep>(value)));
    } else {
      detail::copy_value(target, Target(static_cast<rep>(value)));
    }
  } else if constexpr (!detail::argument_accepted<Target, V&&>()) {
    detail::report_argument_type<Target, V&&>();
  } else {
    detail::assign_value(target, std::forward<V>(value));
  }
}

}  // namespace iecoop

#include <iecoop/detail/pop_macros.hpp>
