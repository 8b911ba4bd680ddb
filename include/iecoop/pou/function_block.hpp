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
#include <iecoop/detail/meta.hpp>
#include <iecoop/fault.hpp>
#include <iecoop/pou/attributes.hpp>
#include <iecoop/pou/call_interface.hpp>
#include <iecoop/pou/interface.hpp>
#include <iecoop/pou/named_arguments.hpp>
#include <iecoop/pou/variables.hpp>
#include <iecoop/types/detail/initial_value.hpp>

#include <iecoop/detail/push_macros.hpp>

namespace iecoop {

namespace detail {

/// The lifecycle methods iecoop calls level by level.
enum class lifecycle_method : unsigned char { fb_init, fb_exit };
/// What a level of a block declares of a lifecycle method.
enum class declaration : unsigned char {
  none,           ///< neither it nor a level below
  own,            ///< one method of its own (its signature known)
  inherited,      ///< none of its own; a level below declares one
  unaddressable,  ///< a template, or overloads: called only as an ordinary call
};

template <class M>
struct method_signature {
  static constexpr bool known = false;
  using owner = void;
  using parameters = void;
};
template <class C, class R, class... P>
struct method_signature<R (C::*)(P...)> {
  static constexpr bool known = true;
  using owner = C;
  using parameters = type_list<P...>;
};
template <class C, class R, class... P>
struct method_signature<R (C::*)(P...) noexcept> : method_signature<R (C::*)(P...)> {};

// A class with a member of each lifecycle method's name: derived together with a block, the
// name is ambiguous exactly when the block has a member of that name too (found even when
// the block's method is a template or overloaded, which has no address).
struct fb_init_name {
  int FB_Init;
};
struct fb_exit_name {
  int FB_Exit;
};
template <class L>
struct fb_init_name_probe : L, fb_init_name {};
template <class L>
struct fb_exit_name_probe : L, fb_exit_name {};

}  // namespace detail

/// The door through which iecoop calls a block's body and lifecycle methods. A block that
/// keeps them private grants access with `friend struct iecoop::block_access;`.
struct block_access {
  /// What level L declares of a lifecycle method (detail::declaration).
  template <class L, detail::lifecycle_method M>
  static constexpr detail::declaration declares_lifecycle() noexcept {
    if constexpr (M == detail::lifecycle_method::fb_init) {
      if constexpr (requires { &L::FB_Init; }) {
        return classify<L, decltype(&L::FB_Init)>();
      } else {
        return named_but_unaddressable<L, M>();
      }
    } else {
      if constexpr (requires { &L::FB_Exit; }) {
        return classify<L, decltype(&L::FB_Exit)>();
      } else {
        return named_but_unaddressable<L, M>();
      }
    }
  }
  /// The signature of level L's lifecycle method M (method_signature).
  template <class L, detail::lifecycle_method M>
  struct lifecycle_signature_of {
    using type = detail::method_signature<void>;
  };
  template <class L>
    requires requires { &L::FB_Init; }
  struct lifecycle_signature_of<L, detail::lifecycle_method::fb_init> {
    using type = detail::method_signature<decltype(&L::FB_Init)>;
  };
  template <class L, detail::lifecycle_method M>
  using lifecycle_signature = typename lifecycle_signature_of<L, M>::type;

  /// Level L's own FB_Init (not an override: CODESYS runs each level's) on the whole block.
  template <class L, class B, class... P>
  static auto fb_init_of(B& block, P&&... params)
      -> decltype(static_cast<L&>(block).L::FB_Init(std::forward<P>(params)...)) {
    return static_cast<L&>(block).L::FB_Init(std::forward<P>(params)...);
  }
  /// Level L's own FB_Exit on the whole block.
  template <class L, class B>
  static auto fb_exit_of(B& block, BOOL in_copy_code) -> decltype(static_cast<L&>(block).L::FB_Exit(in_copy_code)) {
    return static_cast<L&>(block).L::FB_Exit(in_copy_code);
  }

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

 private:
  /// L has a member of the probe's name that has no address (a template, or overloads).
  template <class L, detail::lifecycle_method M>
  static constexpr detail::declaration named_but_unaddressable() noexcept {
    if constexpr (std::is_final_v<L>) {
      // A FINAL block cannot be probed by derivation; it is no base level, so its own FB_Init
      // (found by run_fb_init with the arguments at hand) or FB_Exit is an ordinary call.
      if constexpr (M == detail::lifecycle_method::fb_exit && requires(L& l) { fb_exit(l, BOOL{}); }) {
        return detail::declaration::unaddressable;
      }
      return detail::declaration::none;
    } else if constexpr (M == detail::lifecycle_method::fb_init) {
      if constexpr (requires { &detail::fb_init_name_probe<L>::FB_Init; }) return detail::declaration::none;
      return detail::declaration::unaddressable;
    } else {
      if constexpr (requires { &detail::fb_exit_name_probe<L>::FB_Exit; }) return detail::declaration::none;
      return detail::declaration::unaddressable;
    }
  }
  template <class L, class Pointer>
  static constexpr detail::declaration classify() noexcept {
    using signature = detail::method_signature<Pointer>;
    if constexpr (!signature::known) {
      return detail::declaration::unaddressable;  // const, volatile or ref-qualified: called as an ordinary call
    } else if constexpr (std::is_same_v<typename signature::owner, L>) {
      return detail::declaration::own;
    } else {
      return detail::declaration::inherited;
    }
  }
};

namespace detail {

template <class B>
concept has_body = requires(B& b) { block_access::body(b); };

// A class with a member named body: derived together with a block, the name is ambiguous
// exactly when the block has a member of that name (of any access, a template or overloads).
struct body_name {
  int body;
};
template <class B>
struct body_name_probe : B, body_name {};
/// B has a member named body (its own or inherited), whatever its access.
template <class B>
constexpr bool names_body() noexcept {
  if constexpr (std::is_final_v<B>) {
    return has_body<B> || requires { &B::body; };
  } else {
    return !requires { &body_name_probe<B>::body; };
  }
}

/// No level of B, from B down to the block that extends nothing, has a body of its own (ST:
/// each level's implementation is empty): B is only extended, never called.
template <class B>
constexpr bool bodiless() noexcept {
  using base = typename base_of<B>::type;
  if constexpr (std::is_void_v<base>) {
    return !names_body<B>();
  } else {
    return !block_access::declares_own_body<B>() && bodiless<base>();
  }
}

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

/// Each pin of B starts as ST says: a pin of a C++ scalar type (an enumeration) has an initial
/// value (told where B can be constructed in a constant expression; iecoop-check tells the
/// rest), a STRUCT pin's members have theirs.
template <class B, class Pins, std::size_t... I>
constexpr bool pins_start_defined(std::index_sequence<I...>) {
  constexpr std::size_t count = sizeof...(I);
  constexpr std::size_t undefined = [] {
    std::size_t found = count;
    ((found == count && member_left_undefined<B, pin<Pins, I>>() ? (found = I, 0) : 0), ...);
    return found;
  }();
  if constexpr (undefined < count) {
    // Here, not in a function of its own: one level less between the report and the user's line.
    static_assert(dependent_false<spelled_member_t<pin<Pins, undefined>>>,
                  "iecoop: the VAR_INPUT or VAR_OUTPUT of the block `B` whose name this report spells has a C++ type "
                  "(an enum, int, bool, a pointer) and no initial value: C++ leaves it undefined where the block is "
                  "not value-initialised (a local variable, a member), ST starts it at 0 or at the enumeration's "
                  "first component; write its initial value (`E_State eState = E_State::Idle;`), or give it an IEC "
                  "type (INT, BOOL, POINTER_TO<T>)");
    return false;
  } else {
    return (require_st_start<std::remove_cvref_t<decltype(std::declval<B&>().*pin<Pins, I>)>>() && ...);
  }
}

/// B's VAR_INPUT and VAR_OUTPUT pins.
template <class B>
using start_pins_t = typename concat_pins<inputs_of<B>, outputs_of<B>>::type;

template <class B>
constexpr void check_pins_start() {
  using pins = start_pins_t<B>;
  static_assert((pins_start_defined<B, pins>(std::make_index_sequence<pins::size>{}), true));  // says what is wrong
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
    } else if constexpr (bodiless<B>() && (std::is_polymorphic_v<B> || !std::is_void_v<typename base_of<B>::type>)) {
      static_assert(has_body<B>,
                    "iecoop: the block has no body on any level (an ABSTRACT block whose implementation is empty), "
                    "so it is only extended: C++ cannot dispatch a call of it, nor one through a reference to it, to "
                    "the body of the block extending it; call that block, or give this one its empty body "
                    "`virtual void body() {}` (`void body() override {}` in a block that EXTENDS another)");
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
  check_pins_start<B>();
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
/// `Attributes` are Self's own attribute pragmas (pou/attributes.hpp).
template <class Self, class Attributes = attributes<>>
class block_calls {
 public:
  /// ST: `inst();` — runs the body with the inputs as they are.
  void operator()() {
    if constexpr (lists_attribute<Attributes, no_explicit_call>) {
      static_assert(
          dependent_false<Self>,
          "iecoop: the block is declared no_explicit_call ({attribute 'no_explicit_call'}), so its instance is "
          "not called (ST: inst(); CODESYS error C0554); use its methods and properties, or call a block "
          "that extends it, or drop no_explicit_call from the block's attributes<>");
    } else if constexpr (call_is_valid<Self>()) {
      // The pins' start checked here too: its report is then one call from the user's line.
      static_assert(
          (pins_start_defined<Self, start_pins_t<Self>>(std::make_index_sequence<start_pins_t<Self>::size>{}), true));
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
    if constexpr (lists_attribute<Attributes, no_explicit_call>) {
      static_assert(
          dependent_false<Self>,
          "iecoop: the block is declared no_explicit_call ({attribute 'no_explicit_call'}), so its instance is "
          "not called (ST: inst(); CODESYS error C0554); use its methods and properties, or call a block "
          "that extends it, or drop no_explicit_call from the block's attributes<>");
    } else if constexpr (call_is_valid<Self, A...>()) {
      // The pins' start checked here too: its report is then one call from the user's line.
      static_assert(
          (pins_start_defined<Self, start_pins_t<Self>>(std::make_index_sequence<start_pins_t<Self>::size>{}), true));
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

/// The first of Options... for which Is<Option>::value holds, else Default.
template <template <class> class Is, class Default, class... Options>
struct first_option {
  using type = Default;
};
template <template <class> class Is, class Default, class O, class... Options>
struct first_option<Is, Default, O, Options...> {
  using type = std::conditional_t<Is<O>::value, O, typename first_option<Is, Default, Options...>::type>;
};

/// What a block's declaration lists after the block (and the block it extends): its
/// interfaces as implements<I...> and its attribute pragmas as attributes<...>, each at most once.
template <class... Options>
struct block_options {
  static_assert(((is_implements<Options>::value || is_attributes<Options>::value) && ...) &&
                    (std::size_t{0} + ... + std::size_t{is_implements<Options>::value}) <= 1 &&
                    (std::size_t{0} + ... + std::size_t{is_attributes<Options>::value}) <= 1,
                "iecoop: a block's declaration lists its interfaces as implements<I...> and its attribute pragmas as "
                "attributes<...>, each once: function_block<FB, implements<I_A, I_B>, attributes<no_assign>>, "
                "extends<FB2, FB1, implements<I_C>>");
  using interfaces = typename first_option<is_implements, implements<>, Options...>::type;
  using attributes = typename first_option<is_attributes, iecoop::attributes<>, Options...>::type;
  static_assert(known_attributes<attributes>,
                "iecoop: attributes<...> lists no_explicit_call and no_assign (the attribute pragmas of a block that "
                "iecoop checks); leave out the others: see the porting guide for what each becomes");
};

}  // namespace detail

/**
 * The base of a FUNCTION_BLOCK `Self` (CRTP): `struct FB : iecoop::function_block<FB>`, or
 * `function_block<FB, implements<I_A, I_B>>` for `FUNCTION_BLOCK FB IMPLEMENTS I_A, I_B`;
 * its attribute pragmas follow as `attributes<no_explicit_call, no_assign>` (pou/attributes.hpp).
 *
 * `Self` provides `void body()` (the block's code) and, to be callable with named
 * parameters, lists its interface as `using VAR_INPUT = iecoop::pins<...>` (likewise
 * VAR_OUTPUT and VAR_IN_OUT). Inside the block, `var<T>` declares a local (VAR).
 */
template <class Self, class... Options>
class function_block : public detail::interface_layer_t<Self, detail::no_block<Self>,
                                                        typename detail::block_options<Options...>::interfaces>,
                       public detail::block_calls<Self, typename detail::block_options<Options...>::attributes> {
 public:
  /// VAR ... END_VAR inside Self: readable from outside, written only by Self.
  template <class T>
  using var = local<T, Self>;
  /// The attribute pragmas of Self's declaration.
  using iecoop_attributes = typename detail::block_options<Options...>::attributes;

  function_block() = default;
  function_block(const function_block&) = default;
  function_block& operator=(const function_block&)
    requires(!detail::lists_attribute<iecoop_attributes, no_assign>)
  = default;
  // Declared no_assign: the assignment of a Self (which calls this one) does not compile. Also
  // taken for a move assignment. (The deduced return type has the compilers report it where
  // the assignment is written.)
  auto& operator=(const function_block&)
    requires(detail::lists_attribute<iecoop_attributes, no_assign>)
  {
    static_assert(detail::dependent_false<Self>,
                  "iecoop: the block is declared no_assign ({attribute 'no_assign'}), so one instance of it is not "
                  "assigned to another (ST: fbA := fbB;); assign the variables meant to be copied one by one, or "
                  "drop no_assign from the block's attributes<>");
    return *this;
  }
};

/// A FUNCTION_BLOCK type (made with function_block<> or extends<>).
template <class T>
concept FunctionBlock = detail::has_body<T> && std::is_class_v<T>;

}  // namespace iecoop

#include <iecoop/detail/pop_macros.hpp>
