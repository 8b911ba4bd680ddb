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

/// What a block that extends a block without a body (none of its own on any level, ST: an
/// empty implementation) stands on: that block, with the empty body it has in ST, which
/// SUPER::body() runs (SUPER^();) and the extending block's body overrides.
template <class Base>
class empty_body : public Base {
 public:
  using Base::Base;

 protected:
  virtual void body() {}
};

/// The class extends<Derived, Base> stands on: Base, or — Base names no body at all —
/// empty_body<Base>.
template <class Base>
using body_base_t = std::conditional_t<names_body<Base>(), Base, empty_body<Base>>;

}  // namespace detail

/**
 * `struct Derived : iecoop::extends<Derived, Base>` is ST's `FUNCTION_BLOCK Derived EXTENDS Base`;
 * `extends<Derived, Base, implements<I_A>>` is `... EXTENDS Base IMPLEMENTS I_A`, and
 * `extends<Derived, Base, attributes<no_assign>>` adds Derived's attribute pragmas.
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
 *
 * A Base without a body (ST: an ABSTRACT block whose implementation is empty, often marked
 * no_explicit_call) is extended as it is: extends<> gives it the empty body it has in ST,
 * which `SUPER::body()` runs. A block without a body on any level is only extended — a call
 * of it, or through a reference to it, is refused at compile time (C++ has no body there to
 * dispatch to the derived one's); so Derived may leave out its body too, and is then only
 * extended as well.
 */
// The first and last bases mark where Base's construction as a part of Derived begins and
// ends, so that FB_Init and FB_Exit run on the whole block (pou/lifecycle.hpp); both are empty.
template <class Derived, class Base, class... Options>
class extends : detail::base_construction_begins<Base>,
                public detail::interface_layer_t<Derived, detail::body_base_t<Base>,
                                                 typename detail::block_options<Options...>::interfaces>,
                public detail::block_calls<Derived, typename detail::block_options<Options...>::attributes>,
                detail::base_construction_ends<Derived, Base> {
  using layer = detail::interface_layer_t<Derived, detail::body_base_t<Base>,
                                          typename detail::block_options<Options...>::interfaces>;
  using calls = detail::block_calls<Derived, typename detail::block_options<Options...>::attributes>;

  static_assert(!std::is_final_v<Base>, "iecoop: a FINAL block cannot be extended");
  static_assert(std::is_polymorphic_v<detail::body_base_t<Base>>,
                "iecoop: a block that is extended must dispatch its body virtually, as CODESYS does: declare "
                "`virtual void body()` in the base block (and override it in the derived one)");
  // A base with virtual functions but a non-virtual body would still run its own body when
  // called through a base reference; this fails to compile in that case.
  static_assert(std::is_polymorphic_v<detail::virtual_body_probe<detail::body_base_t<Base>>>);

 public:
  /// ST's SUPER^: the base block (`SUPER::M()`, `SUPER::body()`) — for a base without a
  /// body, the base with its empty body.
  using SUPER = detail::body_base_t<Base>;
  /// The base block, for iecoop's bookkeeping of inherited pins.
  using iecoop_base_block = Base;
  /// The attribute pragmas of Derived's declaration (not Base's).
  using iecoop_attributes = typename detail::block_options<Options...>::attributes;
  template <class T>
  using var = local<T, Derived>;

  using layer::layer;
  extends() = default;
  extends(const extends&) = default;
  extends(extends&&) = default;
  extends& operator=(const extends&)
    requires(!detail::refuses_assignment<extends>())
  = default;
  extends& operator=(extends&&)
    requires(!detail::refuses_assignment<extends>())
  = default;
  // Derived, or a block it extends, is declared no_assign: the assignment of a Derived (which
  // calls this one) does not compile. Also taken for a move assignment.
  auto& operator=(const extends&)
    requires(detail::refuses_assignment<extends>())
  {
    static_assert(detail::dependent_false<Derived>,
                  "iecoop: the block, or a block it EXTENDS, is declared no_assign ({attribute 'no_assign'}), so one "
                  "instance of it is not assigned to another (ST: fbA := fbB;); assign the variables meant to be "
                  "copied one by one, or drop no_assign from that block's attributes<>");
    return *this;
  }
  // Derived's calls, not Base's.
  using calls::operator();
  using calls::with;

 protected:
  // In CODESYS a derived block's implementation replaces its base's, and only SUPER^() runs
  // the base's; C++ would inherit Base's body. So Derived states its own, which overrides this
  // one; this one only exists to say so (compiled with the block's vtable, wherever a Derived
  // is constructed) — unless no level below has a body either: then Derived's is as empty as
  // theirs, as in ST, and this is it (SUPER::body() of a block extending Derived; Derived is
  // only extended, like Base). As noexcept as Base's, which C++ requires of an override.
  void body() noexcept(detail::body_is_noexcept<detail::body_base_t<Base>>) override {
    static_assert(block_access::declares_own_body<Derived>() || detail::bodiless<Base>(),
                  "iecoop: a block that EXTENDS another states its own body, as CODESYS does not run the base's "
                  "implementation for it: write `void body() override { SUPER::body(); }` to run the base's "
                  "(ST: SUPER^();), or `void body() override {}` for an empty implementation");
  }
};

}  // namespace iecoop

#include <iecoop/detail/pop_macros.hpp>
