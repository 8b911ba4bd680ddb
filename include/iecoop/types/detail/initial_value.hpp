// SPDX-License-Identifier: MIT
// iecoop/types/detail/initial_value.hpp — what a variable starts at where its declaration gives no
// initial value: ST starts every variable at its type's initial value (0, FALSE, '', T#0s, the
// first component of an enumeration), where C++ leaves a default-initialised scalar (an enum,
// an int, a pointer) undefined and value-initialises an enum to 0, which need not be a component.
// IWYU pragma: private, include <iecoop/iecoop.hpp>
//
//   initial_value<T>()           ST's initial value of T: an enumeration's first component
//                                (types/enumeration.hpp: enum_start), else T{}; what iecoop's
//                                variables (var<>, temp<>, output<>, retain<>, ARRAY elements)
//                                start at
//   require_st_start<T>()        refuses a STRUCT (a plain aggregate) with a member of a C++
//                                scalar type that has no initial value in the STRUCT: wherever
//                                the STRUCT is default-initialised (a local, a member of a
//                                block constructed as a local), that member would be undefined
//   member_left_undefined<C, M>  default-initialising C leaves its scalar member M undefined
//                                (told by constant evaluation: only where C can be constructed
//                                in a constant expression)
//
// The members of the IEC types (elementary.hpp, string.hpp, ...) all have initial values, so
// every IEC type starts defined in every position; what iecoop cannot see (a C++ enum or int
// declared as a member of a block and named nowhere, or as a local) iecoop-check reports
// (check `uninitialised`, docs/iecoop-check.md).
#pragma once

#include <cstddef>
#include <type_traits>
#include <utility>

#include <iecoop/config.hpp>
#include <iecoop/detail/diagnostics.hpp>
#include <iecoop/detail/meta.hpp>
#include <iecoop/detail/reflect.hpp>
#include <iecoop/types/elementary.hpp>  // first: its diagnostics stay near the top of the compiler's output
#include <iecoop/types/enumeration.hpp>

#include <iecoop/detail/push_macros.hpp>

namespace iecoop::detail {

/// A C++ scalar (an enum, an arithmetic type, a pointer): default-initialised, it is undefined.
template <class T>
concept raw_scalar = std::is_scalar_v<T>;

/// Reads the scalar v (in a constant expression, reading an undefined value is an error).
template <class T>
constexpr bool read_scalar(const T& v) noexcept {
  const T copy = v;
  (void)copy;
  return true;
}

/// P::run() is a constant expression.
template <class P>
concept evaluates = requires { typename std::bool_constant<P::run()>; };

template <class C>
struct construct_probe {
  static constexpr bool run() {
    C object;
    (void)object;
    return true;
  }
};
template <class C, auto Member>
struct member_probe {
  static constexpr bool run() {
    C object;
    return read_scalar(object.*Member);
  }
};
template <class S, std::size_t I>
struct field_probe {
  static constexpr bool run() {
    S object;
    return read_scalar(get_field<I>(object));
  }
};

/// C can be default-initialised in a constant expression (so the probes below can tell).
template <class C>
constexpr bool probe_constructs() noexcept {
  if constexpr (std::is_default_constructible_v<C> && std::is_destructible_v<C>) {
    return evaluates<construct_probe<C>>;
  } else {
    return false;
  }
}

/// Default-initialising C leaves its scalar member `Member` undefined (where C can be
/// constructed in a constant expression; elsewhere this cannot tell and says false).
template <class C, auto Member>
constexpr bool member_left_undefined() noexcept {
  using M = std::remove_cvref_t<decltype(std::declval<C&>().*Member)>;
  if constexpr (raw_scalar<M>) {
    if constexpr (probe_constructs<C>()) {
      return !evaluates<member_probe<C, Member>>;
    } else {
      return false;
    }
  } else {
    return false;
  }
}

/// Converts only to a base class of T: `T{base_probe<T>{}}` compiles where T's first element
/// is a base (a STRUCT that EXTENDS another, a block).
template <class T>
struct base_probe {
  template <class B>
    requires(std::is_base_of_v<B, T> && !std::is_same_v<B, T>)
  operator B&() const noexcept;  // implicit: only in an unevaluated test
};
template <class T>
concept aggregate_with_base = requires { T{base_probe<T>{}}; };

/// A STRUCT whose members iecoop reads one by one: an aggregate class without a base (a
/// STRUCT that EXTENDS another is not read member by member), not an ARRAY.
template <class T>
concept plain_struct = std::is_class_v<T> && !std::is_union_v<T> && std::is_aggregate_v<T> &&
                       !requires { typename T::iecoop_array; } && !aggregate_with_base<T> && Reflectable<T>;

/// The scalar member I of the STRUCT S is undefined where S is default-initialised.
template <class S, std::size_t I>
constexpr bool field_left_undefined() noexcept {
  if constexpr (raw_scalar<field_type<S, I>>) {
    if constexpr (probe_constructs<S>()) {
      return !evaluates<field_probe<S, I>>;
    } else {
      return false;
    }
  } else {
    return false;
  }
}

template <class S>
constexpr std::size_t first_field_left_undefined() noexcept {
  return []<std::size_t... I>(std::index_sequence<I...>) {
    std::size_t found = sizeof...(I);
    ((found == sizeof...(I) && field_left_undefined<S, I>() ? (found = I, 0) : 0), ...);
    return found;
  }(std::make_index_sequence<field_count<S>>{});
}

template <class S, std::size_t I, std::size_t... C>
auto spell_struct_member(std::index_sequence<C...>) -> spelled<field_name<S, I>[C]...>;
/// The name of the I-th member of the STRUCT S, spelled (for diagnostics).
template <class S, std::size_t I>
using spelled_struct_member_t =
    decltype(spell_struct_member<S, I>(std::make_index_sequence<field_name<S, I>.size()>{}));

template <class T>
constexpr bool require_st_start();

template <class S, std::size_t... I>
constexpr bool members_start_defined(std::index_sequence<I...>) {
  return (require_st_start<field_type<S, I>>() && ...);
}

/**
 * T starts as ST says wherever it is declared: a STRUCT whose members of C++ scalar types all
 * have initial values (checked member by member, nested STRUCTs and ARRAY elements too, where
 * the STRUCT can be constructed in a constant expression); refuses the first member without
 * one. Other types are taken as they are.
 */
template <class T>
constexpr bool require_st_start() {
  if constexpr (requires { typename T::iecoop_array; }) {
    return require_st_start<typename T::value_type>();
  } else if constexpr (plain_struct<T>) {
    constexpr std::size_t undefined = first_field_left_undefined<T>();
    if constexpr (undefined < field_count<T>) {
      // Here, not in a function of its own: one level less between the report and the user's line.
      static_assert(
          dependent_false<spelled_struct_member_t<T, undefined>>,
          "iecoop: a member of the STRUCT `T` (its name spelled in this report) has a C++ type (an enum, int, bool, a "
          "pointer) and no initial value: C++ leaves it undefined where the STRUCT is not value-initialised, "
          "ST starts it at 0 or at the enumeration's first component; write its initial value in the "
          "STRUCT (`E_State eState = E_State::Idle;`), or give it an IEC type (INT, BOOL, POINTER_TO<T>)");
      return false;
    } else {
      return members_start_defined<T>(std::make_index_sequence<field_count<T>>{});
    }
  } else {
    return true;
  }
}

/// ST's initial value of a variable of type T declared without one: an enumeration's declared
/// initial value or first component (refused where iecoop does not know it), else T{} (0,
/// FALSE, '', the IEC types' own initial values, a STRUCT's members' initial values).
template <class T>
constexpr T initial_value() {
  if constexpr (std::is_enum_v<T>) {
    return enum_start<T>();
  } else {
    static_assert((require_st_start<T>(), true));  // its own static_assert says what is wrong
    return T{};
  }
}

/// The value of a stand-in variable (a null pointer's target, an unbound in-out's, after the
/// fault): T's initial value where iecoop knows it, else T() (an enumeration whose start is not
/// declared starts at 0 here rather than refusing every in_out<E> and POINTER_TO<E>).
template <class T>
constexpr T stand_in_value() {
  if constexpr (std::is_enum_v<T>) {
    if constexpr (knows_enum_start<T>) {
      return enum_start<T>();
    } else {
      return T();
    }
  } else {
    return T();
  }
}

/// Sets a stand-in variable back to stand_in_value<T>() before it is handed out again. A block
/// declared no_assign (pou/attributes.hpp) is not assigned: it keeps what the last user of the
/// stand-in wrote.
template <class T>
constexpr void refresh_stand_in(T& stand_in) {
  if constexpr (!refuses_assignment<T>()) stand_in = stand_in_value<T>();
}

/// T's initial value is not all zero bytes: a variable of T must be set where C++ zeroes it.
template <class T>
constexpr bool starts_nonzero() noexcept {
  if constexpr (std::is_enum_v<T>) {
    return static_cast<std::underlying_type_t<T>>(enum_start<T>()) != 0;
  } else {
    return false;
  }
}

}  // namespace iecoop::detail

#include <iecoop/detail/pop_macros.hpp>
