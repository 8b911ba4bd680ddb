// SPDX-License-Identifier: MIT
// iecoop/pou/extends.hpp — EXTENDS: a block derived from another block, with SUPER^ and THIS^.
//
//     // FUNCTION_BLOCK fbB EXTENDS fbA
//     struct fbB : iecoop::extends<fbB, fbA> {
//       INT ivar;
//       using VAR_INPUT = iecoop::pins<&fbB::ivar>;   // only what fbB adds
//       void body() override { SUPER::body(); y = y + ivar; }
//     };
#pragma once

#include <type_traits>
#include <utility>

#include <iecoop/config.hpp>
#include <iecoop/pou/function_block.hpp>
#include <iecoop/pou/interface.hpp>
#include <iecoop/pou/lifecycle.hpp>
#include <iecoop/pou/named_arguments.hpp>
#include <iecoop/pou/variables.hpp>

#include <iecoop/detail/push_macros.hpp>

namespace iecoop {

namespace detail {

/// Reads whether Base's body() is noexcept, with the access a derived block has.
template <class Base>
struct body_noexcept_probe : Base {
  static constexpr bool value() noexcept { return noexcept(std::declval<body_noexcept_probe&>().Base::body()); }
};
/// Whether Base's body() is noexcept: an override must be as well.
template <class Base>
inline constexpr bool body_is_noexcept = body_noexcept_probe<Base>::value();

/// Compiles only if Base's body() is virtual ("marked override, but does not override" if not).
template <class Base>
struct virtual_body_probe : Base {
  void body() noexcept(body_is_noexcept<Base>) override {}
};

}  // namespace detail

/**
 * `struct Derived : iecoop::extends<Derived, Base>` is ST's `FUNCTION_BLOCK Derived EXTENDS Base`;
 * `extends<Derived, Base, implements<I_A>>` is `... EXTENDS Base IMPLEMENTS I_A`.
 *
 * Derived is a Base wherever one is expected. Derived states its own body, as in CODESYS the
 * derived block's implementation replaces the base's: `void body() override {}` is an empty
 * implementation, and `SUPER::body()` in it runs the base's (`SUPER^();`). Inside Derived,
 * `SUPER::M()` is ST's `SUPER^.M()` (the base implementation), and
 * `this->M()` is `THIS^.M()` (the most derived override). Base must be polymorphic: CODESYS
 * dispatches the body and methods of a block hierarchy virtually, so declare
 * `virtual void body()` (and `virtual` methods) in the base and `override` them here.
 * `using extends::extends;` makes Derived take Base's constructors; where a level has an
 * FB_Init, give Derived a constructor of its own that calls run_fb_init(*this, ...) instead
 * (an inherited constructor cannot, which is reported as fault_kind::lifecycle).
 */
// The first and last bases mark where Base's construction as a part of Derived begins and
// ends, so that FB_Init and FB_Exit run on the whole block (pou/lifecycle.hpp); both are empty.
template <class Derived, class Base, class Interfaces = implements<>>
class extends : detail::base_construction_begins<Base>,
                public detail::interface_layer_t<Derived, Base, Interfaces>,
                public detail::block_calls<Derived>,
                detail::base_construction_ends<Derived, Base> {
  using layer = detail::interface_layer_t<Derived, Base, Interfaces>;

  static_assert(std::is_polymorphic_v<Base>,
                "iecoop: a block that is extended must dispatch its body virtually, as CODESYS does: declare "
                "`virtual void body()` in the base block (and override it in the derived one)");
  static_assert(!std::is_final_v<Base>, "iecoop: a FINAL block cannot be extended");
  // A base with virtual functions but a non-virtual body would still run its own body when
  // called through a base reference; this fails to compile in that case.
  static_assert(std::is_polymorphic_v<detail::virtual_body_probe<Base>>);

 public:
  /// ST's SUPER^: the base block (`SUPER::M()`, `SUPER::body()`).
  using SUPER = Base;
  /// The base block, for iecoop's bookkeeping of inherited pins.
  using iecoop_base_block = Base;
  template <class T>
  using var = local<T, Derived>;

  using layer::layer;
  // Derived's calls, not Base's.
  using detail::block_calls<Derived>::operator();
  using detail::block_calls<Derived>::with;

 private:
  // In CODESYS a derived block's implementation replaces its base's, and only SUPER^() runs
  // the base's; C++ would inherit Base's body. So Derived states its own, which overrides this
  // one; this one only exists to say so (compiled with the block's vtable, wherever a Derived
  // is constructed). As noexcept as Base's, which C++ requires of an override.
  void body() noexcept(detail::body_is_noexcept<Base>) override {
    static_assert(block_access::declares_own_body<Derived>(),
                  "iecoop: a block that EXTENDS another states its own body, as CODESYS does not run the base's "
                  "implementation for it: write `void body() override { SUPER::body(); }` to run the base's "
                  "(ST: SUPER^();), or `void body() override {}` for an empty implementation");
  }
};

}  // namespace iecoop

#include <iecoop/detail/pop_macros.hpp>
