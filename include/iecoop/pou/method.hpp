// SPDX-License-Identifier: MIT
// iecoop/pou/method.hpp — the variables of a METHOD (and of a FUNCTION): args<Vars>.
//
// A method declares its VAR_INPUT, VAR_IN_OUT and VAR_OUTPUT as a plain struct, with the
// initial values of optional inputs, and takes them as args<Vars>:
//
//     // METHOD PUBLIC DoIt : BOOL
//     // VAR_INPUT iInput_1 : DWORD; iInput_2 : DWORD; sInput_3 : STRING(12); END_VAR
//     struct DoIt_vars {
//       DWORD iInput_1;
//       DWORD iInput_2;
//       STRING<12> sInput_3;
//     };
//     BOOL DoIt(args<DoIt_vars> in) { return in.iInput_1 == in.iInput_2; }
//
// and callers pass the arguments in braces, named in any order, or positionally:
//
//     fb.DoIt({"sInput_3"_ = "Hello World ", "iInput_2"_ = 0xFFFF, "iInput_1"_ = 16});
//     fb.DoIt({16, 0x0010, "Hello World "});
//     fb.DoIt({"iInput_1"_ = 16});        // the others take their declared initial values
//
// Every call starts from the declared initial values (method variables are temporary), an
// output named with `"x"_ >> y` is copied to y when the call's variables end — for a method,
// when the statement containing the call ends (so read y in the next statement); a FUNCTION
// delivers before it returns — and an in-out binds to the variable passed. A one-argument call
// needs no braces: fb.M_Add(3).
#pragma once

#include <cstddef>
#include <type_traits>
#include <utility>

#include <iecoop/config.hpp>
#include <iecoop/detail/diagnostics.hpp>
#include <iecoop/detail/reflect.hpp>
#include <iecoop/pou/named_arguments.hpp>
#include <iecoop/pou/variables.hpp>
#include <iecoop/types/detail/initial_value.hpp>

#include <iecoop/detail/push_macros.hpp>

namespace iecoop {

template <class Vars>
class args;

namespace detail {

/// The names a diagnostic lists: `names_of_variables<spelled<'a'>, spelled<'b'>>`.
template <class... Spelled>
struct names_of_variables {};

template <class T>
struct is_args : std::false_type {};
template <class V>
struct is_args<args<V>> : std::true_type {};

template <class Vars>
constexpr std::size_t find_first_output() noexcept {
  return []<std::size_t... I>(std::index_sequence<I...>) {
    std::size_t found = sizeof...(I);
    ((found == sizeof...(I) && is_output<field_type<Vars, I>>::value ? (found = I, 0) : 0), ...);
    return found;
  }(std::make_index_sequence<field_count<Vars>>{});
}

template <class Vars, std::size_t I, std::size_t... C>
auto spell_field(std::index_sequence<C...>) -> spelled<field_name<Vars, I>[C]...>;
template <class Vars, std::size_t I>
using spelled_field_t = decltype(spell_field<Vars, I>(std::make_index_sequence<field_name<Vars, I>.size()>{}));
template <class Vars, std::size_t... I>
auto spell_fields(std::index_sequence<I...>) -> names_of_variables<spelled_field_t<Vars, I>...>;
/// The names of a METHOD's or FUNCTION's variables, spelled (for diagnostics).
template <class Vars>
using spelled_fields_t = decltype(spell_fields<Vars>(std::make_index_sequence<field_count<Vars>>{}));

/// The argument A names a variable of Vars (positional arguments name none).
template <class Vars, class A>
constexpr bool names_a_variable() noexcept {
  if constexpr (NamedArgument<A>) {
    return field_index<Vars>(std::remove_cvref_t<A>::name) < field_count<Vars>;
  } else {
    return true;
  }
}

template <class Name, class Variables>
constexpr void no_variable_named() {
  static_assert(dependent_false<Name>,
                "iecoop: the METHOD or FUNCTION has no variable of the name spelled in `Name`; `Variables` spells "
                "those it has: check the spelling");
}

/// What a call's argument list must satisfy before any argument is stored, so that a mistake
/// is reported once.
template <class Vars, class... A>
constexpr bool arguments_valid() noexcept {
  constexpr std::size_t positional = (std::size_t{0} + ... + (NamedArgument<A> ? 0 : 1));
  return positional_first<A...>() && distinct_names<A...>() && positional <= field_count<Vars> &&
         (names_a_variable<Vars, A>() && ...);
}
template <class Vars, class... A>
constexpr void report_invalid_arguments() {
  constexpr std::size_t positional = (std::size_t{0} + ... + (NamedArgument<A> ? 0 : 1));
  static_assert(positional_first<A...>(),
                "iecoop: positional arguments come before named ones; name all arguments after the first named one");
  static_assert(distinct_names<A...>(), "iecoop: a call names the same variable twice; name each variable once");
  static_assert(positional <= field_count<Vars>,
                "iecoop: more arguments than the METHOD or FUNCTION has variables; remove the extra ones");
  (
      [] {
        if constexpr (!names_a_variable<Vars, A>()) {
          no_variable_named<spelled_t<std::remove_cvref_t<A>::spelling>, spelled_fields_t<Vars>>();
        }
      }(),
      ...);
}

/// The field I of Vars is an enumeration without an initial value in Vars whose ST initial
/// value is not 0: args<Vars> value-initialises it to 0, and then sets it to its first
/// component (ST initialises a method's variables at every call).
template <class Vars, std::size_t I>
constexpr bool field_starts_late() noexcept {
  if constexpr (std::is_enum_v<field_type<Vars, I>>) {
    if constexpr (field_left_undefined<Vars, I>()) {
      return starts_nonzero<field_type<Vars, I>>();
    } else {
      return false;
    }
  } else {
    return false;
  }
}

/// Sets the variables that value-initialisation does not start as ST does (see field_starts_late).
template <class Vars>
constexpr void start_variables(Vars& vars) {
  if constexpr (Reflectable<Vars>) {
    [&]<std::size_t... I>(std::index_sequence<I...>) {
      static_assert((members_start_defined<Vars>(std::index_sequence<I...>{}), true));  // says what is wrong
      (
          [&] {
            if constexpr (field_starts_late<Vars, I>()) {
              get_field<I>(vars) = enum_start<field_type<Vars, I>>();
            }
          }(),
          ...);
    }(std::make_index_sequence<field_count<Vars>>{});
  }
}

}  // namespace detail

/// The position of the first VAR_OUTPUT in Vars (field_count<Vars> if there is none).
template <Reflectable Vars>
inline constexpr std::size_t first_output_index = detail::find_first_output<Vars>();

namespace detail {
template <class Vars, bool HasOutput = (first_output_index<Vars> < field_count<Vars>)>
struct first_output_of {
  using type = void;  // neither return type nor output: the method returns nothing
};
template <class Vars>
struct first_output_of<Vars, true> {
  using type = typename field_type<Vars, first_output_index<Vars>>::value_type;
};
template <class Vars>
struct first_output_checked {
  static_assert(field_count<Vars> > 0 || std::is_empty_v<Vars>,
                "iecoop: the variables struct is not complete where the method's return type is read: C++ reads the "
                "initial values of a struct nested in a block only after the block. Declare the variables struct "
                "before the block (outside it) when the method returns its first output");
  using type = typename first_output_of<Vars>::type;
};
}  // namespace detail

/// The type of the first VAR_OUTPUT in Vars: the return type of a method declared without
/// one (CODESYS: "the first declared output is used as the return value"); void if Vars has
/// no output either (the method returns nothing). Declare Vars outside the block if it has
/// initial values: C++ completes a nested struct's initial values only after the block.
template <Reflectable Vars>
using first_output_t = typename detail::first_output_checked<Vars>::type;

/**
 * The variables of one call of a METHOD or FUNCTION, built from the call's arguments. It
 * is-a `Vars`, so the body reads them as `in.iInput_1`.
 */
template <class Vars>
class args : public Vars {
  // Vars built once in a constant expression before anything else looks into it: a variable
  // whose constructor refuses its declaration (a temp<E> of an enumeration without a known
  // start) is then reported from Vars's own line, not from inside the field reflection.
  static_assert(requires { typename std::bool_constant<(Vars(), true)>; } || true);
  static_assert(Reflectable<Vars>,
                "iecoop: a METHOD's or FUNCTION's variables are a plain struct (an aggregate of at most 32 fields, "
                "without base classes or C arrays)");

 public:
  using vars_type = Vars;

  /// No arguments: every variable at its declared initial value.
  constexpr args() : Vars() { detail::start_variables<Vars>(*this); }
  constexpr args(const Vars& vars) : Vars(vars) {}  // implicit: the variables, filled elsewhere

  /// Arguments positionally (in declaration order), then named in any order.
  template <class... A>
    requires(sizeof...(A) > 0 && !(sizeof...(A) == 1 && (std::is_base_of_v<Vars, std::remove_cvref_t<A>> && ...)))
  constexpr args(A&&... arguments) : Vars() {  // implicit: a call's argument list
    if constexpr (!detail::arguments_valid<Vars, A...>()) {
      detail::report_invalid_arguments<Vars, A...>();
    } else {
      detail::start_variables<Vars>(*this);
      [&]<std::size_t... K>(std::index_sequence<K...>) {
        (apply<K>(std::forward<A>(arguments)), ...);
      }(std::index_sequence_for<A...>{});
    }
  }

  /// The value of the first VAR_OUTPUT: `return in.first_output();` in a method declared
  /// without return type (its C++ return type is first_output_t<Vars>).
  template <class V = Vars>
    requires(first_output_index<V> < field_count<V>)
  [[nodiscard]] constexpr const first_output_t<V>& first_output() const noexcept {
    return get_field<first_output_index<V>>(static_cast<const V&>(*this)).get();
  }
  /// Nothing, for a method with neither return type nor output (`return in.first_output();`
  /// then fits every method declared without return type).
  template <class V = Vars>
    requires(first_output_index<V> >= field_count<V>)
  constexpr void first_output() const noexcept {}

 private:
  template <std::size_t Position, class A>
  constexpr void apply(A&& argument) {
    using arg = std::remove_cvref_t<A>;
    if constexpr (NamedInput<A>) {
      constexpr std::size_t index = field_index<Vars>(arg::name);
      static_assert(index < field_count<Vars>,
                    "iecoop: the method or function has no variable of this name (see \"name\"_ in the instantiation)");
      store<index>(std::forward<A>(argument).value);
    } else if constexpr (NamedOutput<A>) {
      constexpr std::size_t index = field_index<Vars>(arg::name);
      static_assert(index < field_count<Vars>,
                    "iecoop: the method or function has no variable of this name (see \"name\"_ in the instantiation)");
      using field = field_type<Vars, index>;
      if constexpr (detail::is_output<field>::value) {
        get_field<index>(static_cast<Vars&>(*this)).bind_result(*argument.target);
      } else {
        static_assert(detail::dependent_false<A>,
                      "iecoop: only a VAR_OUTPUT (declared as output<T>) can be read with =>");
      }
    } else {
      static_assert(Position < field_count<Vars>, "iecoop: more arguments than the method or function has variables");
      store<Position>(std::forward<A>(argument));
    }
  }

  template <std::size_t Index, class V>
  constexpr void store(V&& value) {
    using field = field_type<Vars, Index>;
    auto& target = get_field<Index>(static_cast<Vars&>(*this));
    if constexpr (detail::is_in_out<field>::value) {
      static_assert(std::is_lvalue_reference_v<V>,
                    "iecoop: a VAR_IN_OUT needs a variable to refer to, not a value; pass a variable");
      target.bind(value);
    } else if constexpr (detail::is_output<field>::value) {
      static_assert(detail::dependent_false<V>,
                    "iecoop: a VAR_OUTPUT is not passed in; read it after the call with \"name\"_ >> variable");
    } else if constexpr (detail::is_temp<field>::value) {
      static_assert(detail::dependent_false<V>,
                    "iecoop: a METHOD's or FUNCTION's VAR (temp<T>) is its own, not passed by the caller; pass only "
                    "its inputs and in-outs, and declare the VARs after them");
    } else {
      assign_argument(target, std::forward<V>(value));
    }
  }
};

namespace detail {
template <class F>
struct call_signature {
  using parameter = void;  // a generic or mutable lambda: rejected by function<>'s static_assert
};
template <class C, class R, class P>
struct call_signature<R (C::*)(P) const> {
  using parameter = std::remove_cvref_t<P>;
};
template <class C, class R, class P>
struct call_signature<R (C::*)(P) const noexcept> {
  using parameter = std::remove_cvref_t<P>;
};
}  // namespace detail

/**
 * A FUNCTION: stateless code with one return value and any number of extra outputs, made
 * from a lambda that takes its variables as args<Vars>.
 *
 *     // FUNCTION F_Add : INT  VAR_INPUT a, b : INT; END_VAR  VAR_OUTPUT carry : BOOL; END_VAR
 *     struct F_Add_vars { INT a; INT b; output<BOOL> carry; };
 *     inline constexpr iecoop::function F_Add = [](args<F_Add_vars> in) -> INT { ... };
 *
 *     INT s = F_Add("a"_ = 1, "b"_ = 2, "carry"_ >> c);  // ST: s := F_Add(a := 1, b := 2, carry => c);
 *     INT t = F_Add(1, 2);                              // ST: t := F_Add(1, 2);
 */
template <class Impl>
class function {
  using vars_args = typename detail::call_signature<decltype(&Impl::operator())>::parameter;
  static_assert(detail::is_args<vars_args>::value,
                "iecoop: a FUNCTION is made from a non-generic, non-mutable lambda taking its variables as one "
                "parameter of type args<Vars>: [](args<F_vars> in) -> R { ... }");

 public:
  constexpr function(Impl impl) noexcept : impl_(impl) {}  // implicit: `function F = [](args<V>) {...};`

  template <class... A>
  constexpr decltype(auto) operator()(A&&... arguments) const {
    return impl_(vars_args(std::forward<A>(arguments)...));
  }
  /// The same call with the arguments in braces, as methods take them.
  constexpr decltype(auto) operator()(vars_args arguments) const { return impl_(std::move(arguments)); }

 private:
  Impl impl_;
};
template <class Impl>
function(Impl) -> function<Impl>;

}  // namespace iecoop

#include <iecoop/detail/pop_macros.hpp>
