// SPDX-License-Identifier: MIT
// iecoop/pou/attributes.hpp — the attribute pragmas of a FUNCTION_BLOCK that the compiler checks:
// {attribute 'no_explicit_call'} and {attribute 'no_assign'}, listed in the block's declaration.
//
//     // {attribute 'no_explicit_call' := 'use the methods'}
//     // {attribute 'no_assign'}
//     // FUNCTION_BLOCK ABSTRACT FB_Axis IMPLEMENTS I_Axis
//     struct FB_Axis : function_block<FB_Axis, implements<I_Axis>, attributes<no_explicit_call, no_assign>> { ... };
//     // FUNCTION_BLOCK FB_Linear EXTENDS FB_Axis
//     struct FB_Linear : extends<FB_Linear, FB_Axis> { ... };          // its own attributes: none
//
//     fbAxis();              // refused: FB_Axis is no_explicit_call (CODESYS C0554)
//     fbLinear();            // fine: the attribute belongs to FB_Axis, not to the blocks extending it
//     fbAxisA = fbAxisB;     // refused: FB_Axis is no_assign
//     fbLinearA = fbLinearB; // refused as well: the assignment would copy an FB_Axis
//
// `no_explicit_call` refuses `inst()` and `inst(In := x, ...)` of that block type — also through a
// reference to it — and nothing else: its methods, properties and inputs are used as ever. It
// belongs to the block that lists it. `no_assign` refuses assigning one instance to another
// (`fbA = fbB;`, and `fbA = std::move(fbB);`); a block that extends a no_assign block, or has one
// as a member, cannot be assigned either. A copy made by construction (an online change, a
// stand-in after a fault) is not an assignment and stays possible. Neither changes the block's
// size or anything else it does. (CODESYS's 'no_assign_warning' has no counterpart: C++ warns
// only in its own terms; use no_assign.)
#pragma once

#include <type_traits>

#include <iecoop/config.hpp>
#include <iecoop/detail/meta.hpp>

#include <iecoop/detail/push_macros.hpp>

namespace iecoop {

/// {attribute 'no_explicit_call'}: the block's instances are not called, only their methods.
struct no_explicit_call {};
/// {attribute 'no_assign'}: an instance of the block is not assigned to another.
struct no_assign {};

namespace detail {
template <class A>
inline constexpr bool is_block_attribute = std::is_same_v<A, no_explicit_call> || std::is_same_v<A, no_assign>;
}  // namespace detail

/**
 * The attribute pragmas of a FUNCTION_BLOCK, listed after its interfaces in its declaration:
 * `function_block<FB, attributes<no_explicit_call>>`,
 * `extends<FB2, FB1, implements<I_A>, attributes<no_assign>>`.
 */
template <class... A>
struct attributes {
  /// no_assign is listed (read by detail::refuses_assignment, detail/meta.hpp).
  static constexpr bool iecoop_no_assign = (std::is_same_v<A, no_assign> || ...);
  static_assert((detail::is_block_attribute<A> && ...),
                "iecoop: attributes<...> lists no_explicit_call and no_assign (the attribute pragmas of a block that "
                "iecoop checks); leave out the others: see the porting guide for what each becomes");
};

namespace detail {

template <class T>
struct is_attributes : std::false_type {};
template <class... A>
struct is_attributes<attributes<A...>> : std::true_type {};

/// Every entry of the attribute list Attributes is one iecoop knows.
template <class Attributes>
inline constexpr bool known_attributes = false;
template <class... As>
inline constexpr bool known_attributes<attributes<As...>> = (is_block_attribute<As> && ...);

/// The attribute list Attributes contains A.
template <class Attributes, class A>
inline constexpr bool lists_attribute = false;
template <class... As, class A>
inline constexpr bool lists_attribute<attributes<As...>, A> = (std::is_same_v<As, A> || ...);

}  // namespace detail

}  // namespace iecoop

#include <iecoop/detail/pop_macros.hpp>
