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
// C++ then gives CODESYS's order for free: a base block's FB_Init runs before the derived
// block's (base classes are constructed first), FB_Exit of the derived block before the
// base's, and every block nested in another is initialised and exited with it. The flags
// passed are those of the operation under way: (TRUE, FALSE) for a first start.
#pragma once

#include <cstddef>
#include <cstdint>
#include <memory>
#include <new>
#include <type_traits>
#include <utility>

#include <iecoop/config.hpp>
#include <iecoop/detail/lifecycle_state.hpp>
#include <iecoop/pou/function_block.hpp>
#include <iecoop/pou/named_arguments.hpp>
#include <iecoop/types/elementary.hpp>

#include <iecoop/detail/push_macros.hpp>

namespace iecoop {

namespace detail {

template <class B>
concept has_fb_exit = requires(B& b) { block_access::fb_exit(b, BOOL{}); };
template <class B>
concept has_fb_reinit = requires(B& b) { block_access::fb_reinit(b); };

}  // namespace detail

/**
 * Calls the block's own FB_Init(bInitRetains, bInCopyCode, params...) with the flags of the
 * operation under way, then assigns the named initial values of the instance declaration,
 * which, as in CODESYS, overwrite what FB_Init wrote. Call it from the block's constructor:
 * `explicit FB(Valve& v, NamedInput auto&&... init) { iecoop::run_fb_init(*this, v, init...); }`.
 */
template <class B, class... P>
void run_fb_init(B& block, P&&... params_then_initial_values) {
  static_assert(detail::positional_first<P...>(),
                "iecoop: run_fb_init takes FB_Init's parameters first, then the named initial values");
  constexpr std::size_t named = (0 + ... + (NamedInput<P> ? 1 : 0));
  constexpr std::size_t params = sizeof...(P) - named;
  auto arguments = std::forward_as_tuple(std::forward<P>(params_then_initial_values)...);
  [&]<std::size_t... I, std::size_t... J>(std::index_sequence<I...>, std::index_sequence<J...>) {
    static_assert(
        requires { block_access::fb_init(block, BOOL{}, BOOL{}, std::get<I>(std::move(arguments))...); },
        "iecoop: the block has no FB_Init(BOOL bInitRetains, BOOL bInCopyCode, <these parameters>)");
    if (detail::current_lifecycle.init_suppressed) return;  // a probe of the layout, no instance
    block_access::fb_init(block, BOOL(detail::current_lifecycle.init_retains),
                          BOOL(detail::current_lifecycle.in_copy_code), std::get<I>(std::move(arguments))...);
    detail::assign_initial_values(block, std::get<params + J>(std::move(arguments))...);
  }(std::make_index_sequence<params>{}, std::make_index_sequence<named>{});
}

/// Calls the block's FB_Exit(bInCopyCode) with the flag of the operation under way. Call it
/// from the block's destructor.
template <class B>
void run_fb_exit(B& block) {
  static_assert(detail::has_fb_exit<B>, "iecoop: the block has no FB_Exit(BOOL bInCopyCode)");
  if (!detail::current_lifecycle.exit_suppressed) {
    block_access::fb_exit(block, BOOL(detail::current_lifecycle.in_copy_code));
  }
}

/**
 * First start (CODESYS: the first download): constructs an instance in `storage` with the
 * declaration's FB_Init parameters; FB_Init runs with bInitRetains = TRUE,
 * bInCopyCode = FALSE. An instance declared as an ordinary C++ variable gets exactly this.
 */
template <class T, class... A>
T& first_start(void* storage, A&&... args) noexcept {
  detail::lifecycle_scope initialising({true, false, false, false});
  return *std::construct_at(static_cast<T*>(storage), std::forward<A>(args)...);
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
    std::destroy_at(&instance);
  }
  detail::lifecycle_scope initialising({kind != reset_kind::warm, false, false, false});
  return *std::construct_at(&instance, std::forward<A>(args)...);
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
  alignas(T) unsigned char saved_storage[sizeof(T)];
  T* saved = std::construct_at(reinterpret_cast<T*>(saved_storage), std::as_const(old_instance));
  {
    detail::lifecycle_scope exiting({false, true, false, false});
    std::destroy_at(&old_instance);
  }
  T* fresh = nullptr;
  {
    detail::lifecycle_scope initialising({false, true, false, false});
    fresh = std::construct_at(static_cast<T*>(storage), std::forward<A>(args)...);
  }
  {
    detail::lifecycle_scope copying({false, true, false, true});
    *fresh = *saved;
  }
  if constexpr (detail::has_fb_reinit<T>) block_access::fb_reinit(*fresh);
  {
    detail::lifecycle_scope discarding({false, false, true, false});
    std::destroy_at(saved);
  }
  return *fresh;
}

}  // namespace iecoop

#include <iecoop/detail/pop_macros.hpp>
