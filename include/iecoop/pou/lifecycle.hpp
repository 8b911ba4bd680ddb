// SPDX-License-Identifier: MIT
// iecoop/pou/lifecycle.hpp — FB_Init, FB_Reinit and FB_Exit, and the operations a runtime
// performs with them: first start, reset (warm, cold, origin) and online change.
//
// A block declares the lifecycle methods it needs, with CODESYS's signatures, and hooks
// them to its construction and destruction:
//
//     struct FB_Cylinder : function_block<FB_Cylinder> {
//       explicit FB_Cylinder(FB_Valve& valve) { iecoop::run_fb_init(*this, valve); }  // FB_Cylinder(valve := v)
//       ~FB_Cylinder() { iecoop::run_fb_exit(*this); }
//       BOOL FB_Init(BOOL bInitRetains, BOOL bInCopyCode, FB_Valve& valve);
//       BOOL FB_Reinit();
//       BOOL FB_Exit(BOOL bInCopyCode);
//     };
//
// The constructor of each level calls run_fb_init, its destructor run_fb_exit; iecoop runs
// them as CODESYS does, on the whole block: the most derived level's call runs the FB_Init of
// every level from the bottom up (a method or property FB_Init calls is the most derived
// override, SA0106's order) and its destructor the FB_Exit of every level from the top down;
// the calls of the base levels do nothing. Every block nested in another is initialised and
// exited with it. The flags passed are those of the operation under way: (TRUE, FALSE) for a
// first start. A derived FB_Init repeats its base's parameters and may add more; declared as
// `FB_Init(BOOL bInitRetains, BOOL bInCopyCode, args<Vars> in)` it takes them by name:
// `FB_Clamp fbClamp{"fMinimum"_ = 0.0, "fMaximum"_ = 100.0};`.
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <new>
#include <tuple>
#include <type_traits>
#include <utility>

#include <iecoop/config.hpp>
#include <iecoop/detail/construction.hpp>
#include <iecoop/detail/lifecycle_state.hpp>
#include <iecoop/detail/meta.hpp>
#include <iecoop/detail/reflect.hpp>
#include <iecoop/pou/attributes.hpp>
#include <iecoop/pou/function_block.hpp>
#include <iecoop/pou/interface.hpp>
#include <iecoop/pou/method.hpp>
#include <iecoop/pou/named_arguments.hpp>
#include <iecoop/types/detail/type_hash.hpp>
#include <iecoop/types/elementary.hpp>

#include <iecoop/detail/push_macros.hpp>

namespace iecoop {

namespace detail {

template <class B>
concept has_fb_exit = requires(B& b) { block_access::fb_exit(b, BOOL{}); };
template <class B>
concept has_fb_reinit = requires(B& b) { block_access::fb_reinit(b); };

/// The block a level EXTENDS (void for the bottom level).
template <class B>
using base_block_t = typename base_of<B>::type;

/// The bottom level of a block: the one that EXTENDS nothing.
template <class B, class Base = base_block_t<B>>
struct bottom_level {
  using type = typename bottom_level<Base>::type;
};
template <class B>
struct bottom_level<B, void> {
  using type = B;
};

/// Where the block's bottom level lies: the same address from every level of the object
/// (no_block<R> is where function_block<R> stands; its constructor reports that address).
template <class B>
const void* root_address(const B& block) noexcept {
  using R = typename bottom_level<B>::type;
  if constexpr (std::is_base_of_v<no_block<R>, R>) {
    return static_cast<const void*>(&static_cast<const no_block<R>&>(static_cast<const R&>(block)));
  } else {
    return static_cast<const void*>(&block);
  }
}

/// Whether some level of B, from B down to the bottom, declares FB_Init (FB_Exit) itself.
template <class B>
constexpr bool chain_declares_fb_init() noexcept {
  if constexpr (std::is_void_v<B>) {
    return false;
  } else {
    constexpr declaration declared = block_access::declares_lifecycle<B, lifecycle_method::fb_init>();
    return declared == declaration::own || declared == declaration::unaddressable ||
           chain_declares_fb_init<base_block_t<B>>();
  }
}
template <class B>
constexpr bool chain_declares_fb_exit() noexcept {
  if constexpr (std::is_void_v<B>) {
    return false;
  } else {
    constexpr declaration declared = block_access::declares_lifecycle<B, lifecycle_method::fb_exit>();
    return declared == declaration::own || declared == declaration::unaddressable ||
           chain_declares_fb_exit<base_block_t<B>>();
  }
}

/// A level below the most derived one must declare FB_Init and FB_Exit so that iecoop can
/// call exactly its own (one non-template method, as CODESYS has one per block).
template <class L, lifecycle_method M>
constexpr bool base_level_addressable() noexcept {
  if constexpr (std::is_void_v<L>) {
    return true;
  } else {
    return block_access::declares_lifecycle<L, M>() != declaration::unaddressable &&
           base_level_addressable<base_block_t<L>, M>();
  }
}

// --- FB_Init's parameters ---------------------------------------------------------------

/// The user parameters of level L's own FB_Init (after bInitRetains and bInCopyCode).
template <class L, class = typename block_access::lifecycle_signature<L, lifecycle_method::fb_init>::parameters>
struct fb_init_parameters {
  using type = type_list<>;
};
template <class L, class R0, class R1, class... P>
struct fb_init_parameters<L, type_list<R0, R1, P...>> {
  using type = type_list<P...>;
};

template <class List>
struct single_args {
  using vars = void;  // FB_Init takes its parameters positionally
};
template <class P>
  requires is_args<std::remove_cvref_t<P>>::value
struct single_args<type_list<P>> {
  using vars = typename std::remove_cvref_t<P>::vars_type;  // FB_Init(BOOL, BOOL, args<Vars> in)
};
/// The variables struct of level L's FB_Init if it takes its parameters as args<Vars> (by
/// name), else void.
template <class L>
using fb_init_vars_t = typename single_args<typename fb_init_parameters<L>::type>::vars;

template <class List>
struct list_size;
template <class... T>
struct list_size<type_list<T...>> : std::integral_constant<std::size_t, sizeof...(T)> {};

/// Whether the named argument A is a parameter of level L's FB_Init (one taken by name).
template <class L, class A>
constexpr bool names_fb_init_parameter_of() noexcept {
  if constexpr (!NamedInput<A> || std::is_void_v<L>) {
    return false;
  } else if constexpr (block_access::declares_lifecycle<L, lifecycle_method::fb_init>() != declaration::own) {
    return false;
  } else if constexpr (std::is_void_v<fb_init_vars_t<L>>) {
    return false;
  } else {
    return field_index<fb_init_vars_t<L>>(std::remove_cvref_t<A>::name) < field_count<fb_init_vars_t<L>>;
  }
}
/// ... of the FB_Init of any level of B.
template <class B, class A>
constexpr bool names_fb_init_parameter() noexcept {
  if constexpr (std::is_void_v<B>) {
    return false;
  } else {
    return names_fb_init_parameter_of<B, A>() || names_fb_init_parameter<base_block_t<B>, A>();
  }
}

/// The indices I (from 0) for which Selected[I] holds.
template <auto Selected>
constexpr auto selected_indices() noexcept {
  constexpr std::size_t count = [] {
    std::size_t n = 0;
    for (const bool s : Selected) n += s ? 1 : 0;
    return n;
  }();
  std::array<std::size_t, count> indices{};
  std::size_t next = 0;
  for (std::size_t i = 0; i < Selected.size(); ++i) {
    if (Selected[i]) indices[next++] = i;
  }
  return indices;
}
template <auto Indices, std::size_t... K>
constexpr auto as_sequence(std::index_sequence<K...>) -> std::index_sequence<Indices[K]...>;
/// An index_sequence of the indices I for which Selected[I] holds.
template <auto Selected>
using selected_sequence = decltype(as_sequence<selected_indices<Selected>()>(
    std::make_index_sequence<selected_indices<Selected>().size()>{}));

/// The arguments of run_fb_init that are FB_Init parameters given by name, and those that
/// are initial values of the block's inputs (the declaration's `:= (...)`).
template <class B, class... A>
inline constexpr std::array<bool, sizeof...(A)> is_named_parameter{names_fb_init_parameter<B, A>()...};
template <class B, class... A>
inline constexpr std::array<bool, sizeof...(A)> is_initial_value{
    (NamedInput<A> && !names_fb_init_parameter<B, A>())...};
template <class L, class... A>
inline constexpr std::array<bool, sizeof...(A)> is_parameter_of{names_fb_init_parameter_of<L, A>()...};

template <class... A>
inline constexpr std::size_t positional_count = (std::size_t{0} + ... + (NamedArgument<A> ? 0 : 1));

/// What level L declares of FB_Init, for a run_fb_init of B with arguments A: a FINAL B
/// whose FB_Init is a template or has overloads (which no probe by derivation can see) is
/// found by calling it with the positional arguments.
template <class B, class Tuple, std::size_t... P>
constexpr bool fb_init_callable_with(std::index_sequence<P...>) noexcept {
  return requires(B& b, std::tuple_element_t<P, Tuple>&&... a) { block_access::fb_init(b, BOOL{}, BOOL{}, a...); };
}
template <class L, class B, class... A>
constexpr declaration fb_init_declared() noexcept {
  constexpr declaration declared = block_access::declares_lifecycle<L, lifecycle_method::fb_init>();
  if constexpr (declared == declaration::none && std::is_same_v<L, B> && std::is_final_v<B>) {
    if constexpr (fb_init_callable_with<B, std::tuple<A&&...>>(std::make_index_sequence<positional_count<A...>>{})) {
      return declaration::unaddressable;
    }
  }
  return declared;
}

/// How many positional arguments level L's own FB_Init takes.
template <class L, std::size_t Given>
constexpr std::size_t positional_taken() noexcept {
  if constexpr (std::is_void_v<fb_init_vars_t<L>>) {
    return list_size<typename fb_init_parameters<L>::type>::value;
  } else {
    return Given < field_count<fb_init_vars_t<L>> ? Given : field_count<fb_init_vars_t<L>>;
  }
}

/// Calls level L's own FB_Init on the whole block: its positional parameters are the first of
/// the declaration's, its named ones those of its names.
template <class L, class B, class Tuple, class... A>
void call_level_fb_init(B& block, BOOL init_retains, BOOL in_copy_code, Tuple& arguments) {
  constexpr std::size_t taken = positional_taken<L, positional_count<A...>>();
  if constexpr (std::is_void_v<fb_init_vars_t<L>>) {
    [&]<std::size_t... P>(std::index_sequence<P...>) {
      block_access::fb_init_of<L>(block, init_retains, in_copy_code, std::get<P>(arguments)...);
    }(std::make_index_sequence<taken>{});
  } else {
    using vars = fb_init_vars_t<L>;
    [&]<std::size_t... P, std::size_t... N>(std::index_sequence<P...>, std::index_sequence<N...>) {
      block_access::fb_init_of<L>(block, init_retains, in_copy_code,
                                  args<vars>(std::get<P>(arguments)..., std::get<N>(arguments)...));
    }(std::make_index_sequence<taken>{}, selected_sequence<is_parameter_of<L, A...>>{});
  }
}

/// Runs the FB_Init of every level of the block from the bottom up to B.
template <class L, class B, class Tuple, class... A>
void run_fb_init_levels(B& block, BOOL init_retains, BOOL in_copy_code, Tuple& arguments) {
  if constexpr (!std::is_void_v<base_block_t<L>>) {
    run_fb_init_levels<base_block_t<L>, B, Tuple, A...>(block, init_retains, in_copy_code, arguments);
  }
  if constexpr (fb_init_declared<L, B, A...>() == declaration::own) {
    call_level_fb_init<L, B, Tuple, A...>(block, init_retains, in_copy_code, arguments);
  } else if constexpr (std::is_same_v<L, B> && fb_init_declared<L, B, A...>() == declaration::unaddressable) {
    // The most derived level's FB_Init is a template or has overloads: called with every
    // positional argument, as an ordinary call.
    [&]<std::size_t... P>(std::index_sequence<P...>) {
      block_access::fb_init(block, init_retains, in_copy_code, std::get<P>(arguments)...);
    }(std::make_index_sequence<positional_count<A...>>{});
  }
}

/// Whether level L (and each level below it) can take the declaration's arguments A.
template <class L, class B, class... A>
constexpr bool levels_accept() noexcept {
  if constexpr (std::is_void_v<L>) {
    return true;
  } else {
    constexpr declaration declared = fb_init_declared<L, B, A...>();
    constexpr std::size_t given = positional_count<A...>;
    bool ok = levels_accept<base_block_t<L>, B, A...>();
    if constexpr (declared == declaration::own) {
      constexpr std::size_t taken = positional_taken<L, given>();
      if constexpr (std::is_void_v<fb_init_vars_t<L>>) {
        ok = ok && taken <= given;
      }
    } else if constexpr (declared == declaration::unaddressable && std::is_same_v<L, B>) {
      ok = ok && requires(B& b, A&&... a) { block_access::fb_init(b, BOOL{}, BOOL{}, a...); };
    }
    return ok;
  }
}

/// The highest level (from B down) whose FB_Init is its own, or void.
template <class L>
struct top_fb_init_level {
  using type =
      std::conditional_t<block_access::declares_lifecycle<L, lifecycle_method::fb_init>() == declaration::own ||
                             block_access::declares_lifecycle<L, lifecycle_method::fb_init>() ==
                                 declaration::unaddressable,
                         L, typename top_fb_init_level<base_block_t<L>>::type>;
};
template <>
struct top_fb_init_level<void> {
  using type = void;
};

/// Every positional argument is taken by the highest FB_Init.
template <class B, class... A>
constexpr bool positional_all_taken() noexcept {
  using top = typename top_fb_init_level<B>::type;
  if constexpr (fb_init_declared<B, B, A...>() == declaration::unaddressable) {
    return true;
  } else if constexpr (std::is_void_v<top>) {
    return positional_count<A...> == 0;
  } else if constexpr (block_access::declares_lifecycle<top, lifecycle_method::fb_init>() ==
                       declaration::unaddressable) {
    return true;
  } else {
    return positional_taken<top, positional_count<A...>>() == positional_count<A...>;
  }
}

/// The first initial value whose name is no input of B, or void.
template <class B, class... A>
struct first_unknown_initial_value {
  using type = void;
};
template <class B, class A0, class... A>
struct first_unknown_initial_value<B, A0, A...> {
  using type = std::conditional_t<!NamedInput<A0> || names_fb_init_parameter<B, A0>() || known_name<B, A0>(),
                                  typename first_unknown_initial_value<B, A...>::type, A0>;
};

}  // namespace detail

/**
 * Runs FB_Init, as CODESYS does, on the whole block: call it from the constructor of every
 * block that has (or EXTENDS a block that has) an FB_Init, with the declaration's FB_Init
 * parameters, then the named initial values of its inputs:
 * `explicit FB(Valve& v, NamedInput auto&&... init) { iecoop::run_fb_init(*this, v, init...); }`.
 *
 * Only the call of the most derived level runs anything: the FB_Init of every level, from
 * the bottom up (CODESYS's order), each on the whole object, so that a method or property it
 * calls is the most derived override (SA0106's order); then the named initial values, which,
 * as in CODESYS, overwrite what FB_Init wrote. A level's FB_Init takes the first of the
 * positional parameters (CODESYS: a derived FB_Init repeats its base's parameters and may
 * add more), or, declared as `BOOL FB_Init(BOOL bInitRetains, BOOL bInCopyCode, args<Vars>
 * in)`, the parameters named after the fields of Vars. The flags are those of the operation
 * under way. A base level's call, made from its constructor while the object is not yet
 * whole, does nothing; a derived block whose constructor does not call run_fb_init leaves its
 * bases' FB_Init unrun, which is reported as fault_kind::lifecycle.
 */
template <class B, class... P>
void run_fb_init(B& block, P&&... params_then_initial_values) {
  static_assert(detail::positional_first<P...>(),
                "iecoop: run_fb_init takes FB_Init's parameters first, then the named initial values");
  static_assert(detail::base_level_addressable<detail::base_block_t<B>, detail::lifecycle_method::fb_init>(),
                "iecoop: a block that others EXTENDS declares FB_Init as a template or with overloads; CODESYS has one "
                "FB_Init per block, which iecoop calls on the whole derived block: declare one FB_Init");
  static_assert(!std::is_void_v<typename detail::top_fb_init_level<B>::type> || sizeof...(P) > 0 ||
                    detail::fb_init_declared<B, B, P...>() == detail::declaration::unaddressable,
                "iecoop: the block has no FB_Init(BOOL bInitRetains, BOOL bInCopyCode, <these parameters>) (nor does a "
                "block it EXTENDS)");
  static_assert(detail::levels_accept<B, B, P...>() && detail::positional_all_taken<B, P...>(),
                "iecoop: the block has no FB_Init(BOOL bInitRetains, BOOL bInCopyCode, <these parameters>): the "
                "positional parameters must be those of the FB_Init of the block (a base's FB_Init takes the first "
                "of them)");
  using unknown = typename detail::first_unknown_initial_value<B, P...>::type;
  if constexpr (!std::is_void_v<unknown>) {
    // Here, not in a helper, so that the user's lines come within a diagnostic's first lines.
    static_assert(detail::dependent_false<detail::spelled_t<std::remove_cvref_t<unknown>::spelling>>,
                  "iecoop: the declaration names a variable (spelled above) that is neither a parameter of the block's "
                  "FB_Init (declared as `FB_Init(BOOL, BOOL, args<Vars>)`) nor a VAR_INPUT or VAR_IN_OUT of the block: "
                  "check the spelling");
  } else {
    if (detail::current_lifecycle.init_suppressed) return;  // a probe of the layout, no instance
    if (detail::fb_init_deferred<B>()) return;              // a base part: the most derived level runs it
    detail::fb_init_runs<B>(detail::root_address(block));
    auto arguments = std::forward_as_tuple(std::forward<P>(params_then_initial_values)...);
    detail::run_fb_init_levels<B, B, decltype(arguments), P...>(
        block, BOOL(detail::current_lifecycle.init_retains), BOOL(detail::current_lifecycle.in_copy_code), arguments);
    [&]<std::size_t... J>(std::index_sequence<J...>) {
      detail::assign_initial_values(block, std::get<J>(std::move(arguments))...);
    }(detail::selected_sequence<detail::is_initial_value<B, P...>>{});
  }
}

namespace detail {

/// Runs the FB_Exit of every level of the block from B down to the bottom.
template <class L, class B>
void run_fb_exit_levels(B& block, BOOL in_copy_code) {
  constexpr declaration declared = block_access::declares_lifecycle<L, lifecycle_method::fb_exit>();
  if constexpr (declared == declaration::own) {
    block_access::fb_exit_of<L>(block, in_copy_code);
  } else if constexpr (declared == declaration::unaddressable && std::is_same_v<L, B>) {
    block_access::fb_exit(block, in_copy_code);
  }
  if constexpr (!std::is_void_v<base_block_t<L>>) run_fb_exit_levels<base_block_t<L>>(block, in_copy_code);
}

}  // namespace detail

/**
 * Runs FB_Exit(bInCopyCode), with the flag of the operation under way: call it from the
 * destructor of every block that has (or EXTENDS a block that has) an FB_Exit. The most
 * derived level's call runs the FB_Exit of every level, from the most derived down (CODESYS's
 * order), each on the whole object; the base levels' calls, made when their destructors run
 * later, do nothing. A derived block whose destructor does not call it is reported as
 * fault_kind::lifecycle (its bases' FB_Exit then run without it).
 */
template <class B>
void run_fb_exit(B& block) {
  static_assert(detail::chain_declares_fb_exit<B>(),
                "iecoop: the block has no FB_Exit(BOOL bInCopyCode) (nor does a block it EXTENDS)");
  static_assert(detail::base_level_addressable<detail::base_block_t<B>, detail::lifecycle_method::fb_exit>(),
                "iecoop: a block that others EXTENDS declares FB_Exit as a template or with overloads; declare one "
                "FB_Exit(BOOL bInCopyCode)");
  if (detail::current_lifecycle.exit_suppressed) return;
  if (detail::fb_exit_ran_for<B>()) return;  // a base level: the most derived one ran it
  if constexpr (!std::is_void_v<detail::base_block_t<B>>) detail::fb_exit_runs<B>();
  detail::run_fb_exit_levels<B>(block, BOOL(detail::current_lifecycle.in_copy_code));
}

namespace detail {

/// extends<Derived, Base>'s first base (see construction.hpp): Base's construction as a part
/// of a Derived begins; its destruction ends the record of the FB_Exit chain at the bottom.
template <class Base>
struct base_construction_begins {
  base_construction_begins() noexcept { begin_base_construction(lifecycle_id<Base>(), this); }
  base_construction_begins(const base_construction_begins&) noexcept {
    begin_base_construction(lifecycle_id<Base>(), this);
  }
  base_construction_begins& operator=(const base_construction_begins&) noexcept = default;
  ~base_construction_begins() { end_fb_exit_record(lifecycle_id<Base>()); }
};

/// extends<Derived, Base>'s last base: Base is complete (see construction.hpp); at
/// destruction, Derived's destructor and members are done and Base's destructor is next.
template <class Derived, class Base>
struct base_construction_ends {
  base_construction_ends() noexcept { end(); }
  base_construction_ends(const base_construction_ends&) noexcept { end(); }
  base_construction_ends& operator=(const base_construction_ends&) noexcept = default;
  ~base_construction_ends() {
    if (current_lifecycle.exit_suppressed) return;
    if (fb_exit_level_done(lifecycle_id<Derived>(), lifecycle_id<Base>())) return;
    if constexpr (chain_declares_fb_exit<Derived>()) {
      lifecycle_fault(
          "a block's destructor does not call run_fb_exit(*this): CODESYS runs the FB_Exit of every "
          "level on the whole block, which C++ can do only from the most derived destructor; the bases' "
          "FB_Exit now run without it. Give the block (the fault's pou) `~Block() { run_fb_exit(*this); }`",
          short_type_name_c<Derived>.data());
    }
  }

 private:
  void end() noexcept {
    end_base_construction(lifecycle_id<Derived>(), lifecycle_id<Base>(), sizeof(Derived),
                          short_type_name_c<Derived>.data());
  }
};

}  // namespace detail

/**
 * First start (CODESYS: the first download): constructs an instance in `storage` with the
 * declaration's FB_Init parameters; FB_Init runs with bInitRetains = TRUE,
 * bInCopyCode = FALSE. An instance declared as an ordinary C++ variable gets exactly this.
 */
template <class T, class... A>
T& first_start(void* storage, A&&... args) noexcept {
  detail::lifecycle_scope initialising({true, false, false, false});
  return *::new (storage) T(std::forward<A>(args)...);
}

/// The resets of a running application (CODESYS: Online → Reset warm/cold/origin).
enum class reset_kind : std::uint8_t {
  warm,    ///< FB_Exit(FALSE), then FB_Init(bInitRetains := FALSE, bInCopyCode := FALSE)
  cold,    ///< FB_Exit(FALSE), then FB_Init(TRUE, FALSE)
  origin,  ///< as cold (and, with the scheduler, PERSISTENT data is dropped too)
};

/**
 * Resets an instance: FB_Exit(FALSE) on it and everything nested in it (derived before
 * base), then constructs it afresh with `args` (the declaration's FB_Init parameters), which
 * runs FB_Init with bInitRetains = (kind != warm), bInCopyCode = FALSE. A new download is
 * reset(x, reset_kind::origin, ...).
 *
 * Pass the instance as its own type, not through a reference to a base block (the instance is
 * rebuilt as the type named here), and parameters that do not refer into the instance. An
 * exception from FB_Init or FB_Exit ends the program (the operation is noexcept).
 */
template <class T, class... A>
T& reset(T& instance, reset_kind kind, A&&... args) noexcept {
  {
    detail::lifecycle_scope exiting({true, false, false, false});
    instance.~T();
  }
  detail::lifecycle_scope initialising({kind != reset_kind::warm, false, false, false});
  return *::new (static_cast<void*>(&instance)) T(std::forward<A>(args)...);
}

/**
 * An online change that relocates an instance to `storage`, in CODESYS's order:
 * old.FB_Exit(bInCopyCode := TRUE); new.FB_Init(bInitRetains := FALSE, bInCopyCode := TRUE);
 * copy of the old instance's data into the new one; new.FB_Reinit(). Returns the new
 * instance; the old one no longer exists. As in CODESYS, pointers into the old instance
 * dangle afterwards, except in-out bindings, which keep what the new instance's construction
 * bound. The same preconditions as for reset() apply.
 */
template <class T, class... A>
T& online_change(T& old_instance, void* storage, A&&... args) noexcept {
  static_assert(std::is_copy_assignable_v<T> && std::is_copy_constructible_v<T>,
                "iecoop: an online change copies the instance; the block must be copyable");
  static_assert(!detail::refuses_assignment<T>(),
                "iecoop: online_change copies the old instance into the new one by assignment, which a block "
                "declared no_assign refuses; relocate it with reset() (its values start anew), or drop no_assign");
  alignas(T) unsigned char saved_storage[sizeof(T)];
  T* saved = ::new (static_cast<void*>(saved_storage)) T(std::as_const(old_instance));
  {
    detail::lifecycle_scope exiting({false, true, false, false});
    old_instance.~T();
  }
  T* fresh = nullptr;
  {
    detail::lifecycle_scope initialising({false, true, false, false});
    fresh = ::new (storage) T(std::forward<A>(args)...);
  }
  {
    detail::lifecycle_scope copying({false, true, false, true});
    if constexpr (!detail::refuses_assignment<T>()) *fresh = *saved;
  }
  if constexpr (detail::has_fb_reinit<T>) block_access::fb_reinit(*fresh);
  {
    detail::lifecycle_scope discarding({false, false, true, false});
    saved->~T();
  }
  return *fresh;
}

}  // namespace iecoop

#include <iecoop/detail/pop_macros.hpp>
