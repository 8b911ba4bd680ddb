// SPDX-License-Identifier: MIT
// iecoop/pou/function_block.hpp — FUNCTION_BLOCK and EXTENDS: a block is a class whose body runs
// on each call, with ST's two call forms.
//
//     // FUNCTION_BLOCK FB_Motor
//     struct FB_Motor : iecoop::function_block<FB_Motor> {
//       BOOL bStart;                 // VAR_INPUT
//       BOOL bRunning;               // VAR_OUTPUT
//       var<INT> nStarts;            // VAR
//       using VAR_INPUT = iecoop::pins<&FB_Motor::bStart>;
//       using VAR_OUTPUT = iecoop::pins<&FB_Motor::bRunning>;
//       void body() {                // the implementation
//         if (bStart & !bRunning) nStarts = nStarts + 1;
//         bRunning = bStart;
//       }
//     };
//
//     motor.bStart = TRUE; motor();                    // ST: motor.bStart := TRUE; motor();
//     motor("bStart"_ = TRUE, "bRunning"_ >> running);  // ST: motor(bStart := TRUE, bRunning => running);
//
// An input left out of a call keeps its value. A block without virtual functions is exactly
// as large as its variables.
#pragma once

#include <cstddef>
#include <string_view>
#include <type_traits>
#include <utility>

#include <iecoop/config.hpp>
#include <iecoop/detail/diagnostics.hpp>
#include <iecoop/detail/lifecycle_state.hpp>
#include <iecoop/fault.hpp>
#include <iecoop/pou/call_interface.hpp>
#include <iecoop/pou/interface.hpp>
#include <iecoop/pou/named_arguments.hpp>
#include <iecoop/pou/variables.hpp>

#include <iecoop/detail/push_macros.hpp>

namespace iecoop {

/// The door through which iecoop calls a block's body and lifecycle methods. A block that
/// keeps them private grants access with `friend struct iecoop::block_access;`.
struct block_access {
  template <class B>
  static auto body(B& block) -> decltype(block.body()) {
    return block.body();
  }
  template <class B, class... P>
  static auto fb_init(B& block, P&&... params) -> decltype(block.FB_Init(std::forward<P>(params)...)) {
    return block.FB_Init(std::forward<P>(params)...);
  }
  template <class B>
  static auto fb_exit(B& block, BOOL in_copy_code) -> decltype(block.FB_Exit(in_copy_code)) {
    return block.FB_Exit(in_copy_code);
  }
  template <class B>
  static auto fb_reinit(B& block) -> decltype(block.FB_Reinit()) {
    return block.FB_Reinit();
  }
  /// B declares `void body()` itself (not only inherits one).
  template <class B>
  static constexpr bool declares_own_body() noexcept {
    if constexpr (requires { &B::body; }) {
      return std::is_same_v<decltype(&B::body), void (B::*)()> ||
             std::is_same_v<decltype(&B::body), void (B::*)() noexcept>;
    } else {
      return false;
    }
  }
};

namespace detail {

template <class B>
concept has_body = requires(B& b) { block_access::body(b); };

template <class B, class Pins, std::size_t... I>
constexpr bool all_bound(const B& block, std::index_sequence<I...>) {
  return ((block.*pin<Pins, I>).bound() && ...);
}

template <class Pins>
inline constexpr bool names_unique = unique_names<Pins>();

template <class B>
constexpr void check_interface() {
  using all = typename concat_pins<typename concat_pins<inputs_of<B>, outputs_of<B>>::type, in_outs_of<B>>::type;
  static_assert(
      names_unique<all>,
      "iecoop: two pins of the block have the same name; a derived block may not redeclare a variable of its base");
}

/// Applies `Name := value` to a block: assigns an input, or binds an in-out.
template <class B, NamedInput A>
constexpr void apply_input(B& block, A&& argument) {
  using arg = std::remove_cvref_t<A>;
  constexpr std::size_t input = inputs_of<B>::index_of(arg::name);
  constexpr std::size_t in_out = in_outs_of<B>::index_of(arg::name);
  if constexpr (input < inputs_of<B>::size) {
    assign_argument(block.*pin<inputs_of<B>, input>, std::forward<A>(argument).value);
  } else if constexpr (in_out < in_outs_of<B>::size) {
    static_assert(std::is_lvalue_reference_v<decltype(argument.value)>,
                  "iecoop: a VAR_IN_OUT needs a variable to refer to, not a value; pass a variable (\"x\"_ = myVar)");
    (block.*pin<in_outs_of<B>, in_out>).bind(argument.value);
  } else {
    static_assert(dependent_false<A>,
                  "iecoop: the block has no VAR_INPUT or VAR_IN_OUT of this name (see \"name\"_ in the instantiation); "
                  "check the spelling, and that the block lists it in VAR_INPUT or VAR_IN_OUT");
  }
}

/// Applies `Name => target` after a call: copies an output to the caller's variable.
template <class B, NamedOutput A>
constexpr void apply_output(const B& block, const A& argument) {
  using arg = std::remove_cvref_t<A>;
  constexpr std::size_t output = outputs_of<B>::index_of(arg::name);
  if constexpr (output < outputs_of<B>::size) {
    deliver_output(*argument.target, block.*pin<outputs_of<B>, output>);
  } else {
    static_assert(dependent_false<A>,
                  "iecoop: the block has no VAR_OUTPUT of this name (see \"name\"_ in the instantiation); only "
                  "outputs can be read with =>, and the block must list them in VAR_OUTPUT");
  }
}

template <class B>
using spelled_inputs_t = typename spelled_pins<typename concat_pins<inputs_of<B>, in_outs_of<B>>::type>::type;
template <class B>
using spelled_outputs_t = typename spelled_pins<outputs_of<B>>::type;

/// The name of argument A is one the block B has (an input or in-out for `:=`, an output for
/// `=>`); a positional argument has none.
template <class B, class A>
constexpr bool known_name() noexcept {
  using arg = std::remove_cvref_t<A>;
  if constexpr (NamedInput<A>) {
    return inputs_of<B>::index_of(arg::name) < inputs_of<B>::size ||
           in_outs_of<B>::index_of(arg::name) < in_outs_of<B>::size;
  } else if constexpr (NamedOutput<A>) {
    return outputs_of<B>::index_of(arg::name) < outputs_of<B>::size;
  } else {
    return true;
  }
}

// The diagnostics of a misspelt name: the function's template arguments spell the name and
// the names the block has, which both compilers print beside the message.
template <class Name, class Inputs>
constexpr void no_VAR_INPUT_or_VAR_IN_OUT_named() {
  static_assert(dependent_false<Name>,
                "iecoop: the block has no VAR_INPUT or VAR_IN_OUT of the name spelled in `Name`; `Inputs` "
                "spells those it has: check the spelling, and that the block lists the variable in "
                "`using VAR_INPUT = pins<...>` (or VAR_IN_OUT)");
}
template <class Name, class Outputs>
constexpr void no_VAR_OUTPUT_named() {
  static_assert(dependent_false<Name>,
                "iecoop: the block has no VAR_OUTPUT of the name spelled in `Name` (only outputs are read with =>); "
                "`Outputs` spells those it has: check the spelling, and that the block lists the variable in "
                "`using VAR_OUTPUT = pins<...>`");
}
template <class B>
constexpr bool is_program() noexcept {
  return requires { typename B::iecoop_program; };
}

/// The argument A, if it names an input of B, has a type that input accepts.
template <class B, class A>
constexpr bool argument_type_ok() noexcept {
  if constexpr (NamedInput<A> && known_name<B, A>()) {
    using arg = std::remove_cvref_t<A>;
    constexpr std::size_t input = inputs_of<B>::index_of(arg::name);
    if constexpr (input < inputs_of<B>::size) {
      using target = std::remove_cvref_t<decltype(std::declval<B&>().*pin<inputs_of<B>, input>)>;
      return argument_accepted<target, decltype(std::declval<A>().value)>();
    } else {
      return true;  // an in-out binds to a variable: checked where it binds
    }
  } else {
    return true;
  }
}
template <class B, class... A>
struct first_mistyped_argument {
  using type = void;
};
template <class B, class A0, class... A>
struct first_mistyped_argument<B, A0, A...> {
  using type = std::conditional_t<argument_type_ok<B, A0>(), typename first_mistyped_argument<B, A...>::type, A0>;
};

/// The first argument of A... whose name the block B does not have, or void.
template <class B, class... A>
struct first_unknown_argument {
  using type = void;
};
template <class B, class A0, class... A>
struct first_unknown_argument<B, A0, A...> {
  using type = std::conditional_t<known_name<B, A0>(), typename first_unknown_argument<B, A...>::type, A0>;
};

/// Everything a call's arguments and the block must satisfy, checked before anything else is
/// instantiated, so that a mistake is one error.
template <class B, class... A>
constexpr bool call_is_valid() {
  return has_body<B> && (known_name<B, A>() && ...) && distinct_names<A...>() && (argument_type_ok<B, A>() && ...);
}
/// What is wrong with a call for which call_is_valid() is false, as one error.
template <class B, class... A>
constexpr void report_invalid_call() {
  if constexpr (!has_body<B>) {
    if constexpr (is_program<B>()) {
      static_assert(has_body<B>,
                    "iecoop: a PROGRAM needs its code as `void body()` (public, or private with "
                    "`friend struct iecoop::block_access;`); write `void body() {}` for an empty implementation");
    } else if constexpr (!std::is_void_v<typename base_of<B>::type>) {
      static_assert(has_body<B>,
                    "iecoop: a block that EXTENDS another states its own body, as CODESYS does not run the base's "
                    "implementation for it: write `void body() override { SUPER::body(); }` to run the base's "
                    "(ST: SUPER^();), or `void body() override {}` for an empty implementation");
    } else {
      static_assert(has_body<B>,
                    "iecoop: a FUNCTION_BLOCK needs its code as `void body()` (public, or private with "
                    "`friend struct iecoop::block_access;`); write `void body() {}` for an empty implementation");
    }
  } else if constexpr (!std::is_void_v<typename first_unknown_argument<B, A...>::type>) {
    using unknown = std::remove_cvref_t<typename first_unknown_argument<B, A...>::type>;
    if constexpr (NamedInput<unknown>) {
      no_VAR_INPUT_or_VAR_IN_OUT_named<spelled_t<unknown::spelling>, spelled_inputs_t<B>>();
    } else {
      no_VAR_OUTPUT_named<spelled_t<unknown::spelling>, spelled_outputs_t<B>>();
    }
  } else if constexpr (!distinct_names<A...>()) {
    static_assert(distinct_names<A...>(), "iecoop: a call names the same variable twice; name each variable once");
  } else {
    using mistyped = std::remove_cvref_t<typename first_mistyped_argument<B, A...>::type>;
    using target =
        std::remove_cvref_t<decltype(std::declval<B&>().*pin<inputs_of<B>, inputs_of<B>::index_of(mistyped::name)>)>;
    using from = nominal_t<passed_t<decltype(std::declval<mistyped>().value)>>;
    using to = unwrapped_t<target&>;
    if constexpr (!iec_name<from>::value.empty() && !iec_name<to>::value.empty()) {
      no_implicit_conversion<spelled_iec_name_t<from>, spelled_iec_name_t<to>>();
    } else {
      report_argument_type<target, decltype(std::declval<mistyped>().value)>();
    }
  }
}

template <class B, class... A>
void call_valid_block(B& block, A&&... arguments) {
  check_interface<B>();
  (
      [&] {
        if constexpr (NamedInput<A>) apply_input(block, std::forward<A>(arguments));
      }(),
      ...);
  using in_outs = in_outs_of<B>;
  if (!all_bound<B, in_outs>(block, std::make_index_sequence<in_outs::size>{})) {
    fault(fault_kind::unbound_in_out,
          "a block was called with a VAR_IN_OUT not bound to a variable; its body did not run");
  } else {
    block_access::body(block);
  }
  (
      [&] {
        if constexpr (NamedOutput<A>) apply_output(block, arguments);
      }(),
      ...);
}

/// One call of a block: inputs, body, outputs (ST: inst(IN := x, Q => y)).
template <class B, class... A>
void call_block(B& block, A&&... arguments) {
  if constexpr (!call_is_valid<B, A...>()) {
    report_invalid_call<B, A...>();
  } else {
    call_valid_block(block, std::forward<A>(arguments)...);
  }
}

template <class B, class... A>
constexpr B& assign_inputs(B& block, A&&... arguments) {
  if constexpr (((known_name<B, A>() && ...) && distinct_names<A...>())) {
    (apply_input(block, std::forward<A>(arguments)), ...);
  } else if constexpr (!std::is_void_v<typename first_unknown_argument<B, A...>::type>) {
    using unknown = std::remove_cvref_t<typename first_unknown_argument<B, A...>::type>;
    no_VAR_INPUT_or_VAR_IN_OUT_named<spelled_t<unknown::spelling>, spelled_inputs_t<B>>();
  } else {
    static_assert(distinct_names<A...>(), "iecoop: a call names the same variable twice; name each variable once");
  }
  return block;
}

/// One named initial value of an instance declaration: as apply_input, except that an input
/// whose kept value a restore gave it at its construction keeps that value (bInitRetains
/// FALSE: the remanent variables are not initialised).
template <class B, NamedInput A>
constexpr void apply_initial_value(B& block, A&& argument) {
  using arg = std::remove_cvref_t<A>;
  constexpr std::size_t input = inputs_of<B>::index_of(arg::name);
  if constexpr (input < inputs_of<B>::size) {
    const auto& field = block.*pin<inputs_of<B>, input>;
    if (kept_at_construction != nullptr && kept_at_construction(&field, sizeof field)) return;
  }
  apply_input(block, std::forward<A>(argument));
}

/// The named initial values of an instance declaration, assigned after FB_Init (run_fb_init):
/// as with(), but a RETAIN or PERSISTENT input restored at its construction keeps its value.
template <class B, NamedInput... A>
constexpr B& assign_initial_values(B& block, A&&... arguments) {
  if constexpr (((known_name<B, A>() && ...) && distinct_names<A...>())) {
    (apply_initial_value(block, std::forward<A>(arguments)), ...);
    return block;
  } else {
    return assign_inputs(block, std::forward<A>(arguments)...);  // its diagnostics
  }
}

/// The two ways to call a block `Self`, and with(): what function_block<> and extends<> add.
template <class Self>
class block_calls {
 public:
  /// ST: `inst();` — runs the body with the inputs as they are.
  void operator()() {
    if constexpr (call_is_valid<Self>()) {
      call_valid_block(self());
    } else {
      report_invalid_call<Self>();
    }
  }

  /// ST: `inst(IN := x, PT := t, Q => q);` — assigns the named inputs (and binds the named
  /// in-outs), runs the body, then copies the named outputs out. Inputs not named keep
  /// their values.
  template <NamedArgument... A>
    requires(sizeof...(A) > 0)
  void operator()(A&&... arguments) {
    if constexpr (call_is_valid<Self, A...>()) {
      call_valid_block(self(), std::forward<A>(arguments)...);
    } else {
      report_invalid_call<Self, A...>();
    }
  }

  /// Assigns named inputs without running the body, and returns the block, so that an
  /// action can follow: ST's `inst.Reset(In := FALSE);` is `inst.with("In"_ = FALSE).Reset();`.
  template <NamedInput... A>
  Self& with(A&&... arguments) {
    return assign_inputs(self(), std::forward<A>(arguments)...);
  }

 private:
  Self& self() noexcept { return static_cast<Self&>(*this); }
};

}  // namespace detail

/**
 * The base of a FUNCTION_BLOCK `Self` (CRTP): `struct FB : iecoop::function_block<FB>`, or
 * `function_block<FB, implements<I_A, I_B>>` for `FUNCTION_BLOCK FB IMPLEMENTS I_A, I_B`.
 *
 * `Self` provides `void body()` (the block's code) and, to be callable with named
 * parameters, lists its interface as `using VAR_INPUT = iecoop::pins<...>` (likewise
 * VAR_OUTPUT and VAR_IN_OUT). Inside the block, `var<T>` declares a local (VAR).
 */
template <class Self, class Interfaces = implements<>>
class function_block : public detail::interface_layer_t<Self, detail::no_block<Self>, Interfaces>,
                       public detail::block_calls<Self> {
 public:
  /// VAR ... END_VAR inside Self: readable from outside, written only by Self.
  template <class T>
  using var = local<T, Self>;
};

/// A FUNCTION_BLOCK type (made with function_block<> or extends<>).
template <class T>
concept FunctionBlock = detail::has_body<T> && std::is_class_v<T>;

}  // namespace iecoop

#include <iecoop/detail/pop_macros.hpp>
