// SPDX-License-Identifier: MIT
// iecoop/pou/interface.hpp — INTERFACE, IMPLEMENTS, interface variables, __QUERYINTERFACE and
// __QUERYPOINTER, without RTTI.
//
//     // INTERFACE I_Math
//     struct I_Math : interface_base<I_Math> {
//       struct M_Add_vars { REAL rVal; };
//       virtual REAL M_Add(args<M_Add_vars> in) = 0;            // METHOD M_Add : REAL
//       virtual REAL P_Result_Get() = 0;                        // PROPERTY P_Result : REAL
//       virtual void P_Result_Set(REAL value) = 0;
//       [[no_unique_address]] property<REAL, &I_Math::P_Result_Get, &I_Math::P_Result_Set> P_Result{this};
//     };
//     // FUNCTION_BLOCK FB_MathMen IMPLEMENTS I_Math
//     struct FB_MathMen : function_block<FB_MathMen, implements<I_Math>> { ... overrides ... };
//     // FUNCTION_BLOCK FB_Logged EXTENDS FB_MathMen IMPLEMENTS I_Log
//     struct FB_Logged : extends<FB_Logged, FB_MathMen, implements<I_Log>> { ... };
//
//     itf<I_Math> ipInterface;          // ipInterface : I_Math;   (0 until assigned)
//     ipInterface = fbMemInstance;      // ipInterface := fbMemInstance;
//     ipInterface->P_Result = 2;        // ipInterface.P_Result := 2;
//     r = ipInterface->M_Add(3);        // r := ipInterface.M_Add(3);
//
// An interface variable is assigned, as in ST, a block implementing the interface, another
// interface variable of it or of an interface that extends it, and any variable form holding
// one: a block's var<itf<I>>, a PROPERTY of interface type, a REFERENCE TO a block or to an
// interface variable.
//
// An interface is an abstract class: a block that misses one of its methods or properties
// cannot be instantiated, and the compiler names what is missing. A call through an
// interface variable is one virtual call. A call through an unassigned one is a fault.
#pragma once

#include <concepts>
#include <cstddef>
#include <cstdlib>
#include <type_traits>

#include <iecoop/config.hpp>
#include <iecoop/detail/construction.hpp>
#include <iecoop/detail/diagnostics.hpp>
#include <iecoop/detail/iec_value.hpp>
#include <iecoop/detail/meta.hpp>
#include <iecoop/fault.hpp>
#include <iecoop/pou/call_interface.hpp>
#include <iecoop/types/detail/value_operators.hpp>
#include <iecoop/types/elementary.hpp>

#include <iecoop/detail/push_macros.hpp>

namespace iecoop {

namespace detail {

/// A type's identity without RTTI: the address of a variable that exists once per type (not
/// const, so that no linker folds two of them into one).
using type_id = const void*;
template <class T>
struct type_tag {
  static inline char tag = 0;
};
template <class T>
constexpr type_id type_id_of() noexcept {
  return &type_tag<T>::tag;
}
/// What a query asks for to get the block itself, whatever its type (__QUERYPOINTER).
struct any_block {};

}  // namespace detail

/**
 * The base of an INTERFACE `Self`; `Bases` are the interfaces it EXTENDS (inherited
 * virtually, so that an interface reached along two ways is one). Declare the methods and
 * property accessors as pure virtual functions, and properties as property<> members.
 */
template <class Self, class... Bases>
class interface_base : public virtual Bases... {
 public:
  /// The interface itself, and the interfaces it extends (for iecoop's queries).
  using iecoop_interface = Self;
  using iecoop_extended = detail::type_list<Bases...>;

  /// The block behind this interface answers __QUERYINTERFACE and __QUERYPOINTER: a pointer
  /// to the part of it that has the asked-for type, or nullptr. Implemented by the block (see implements<>).
  virtual void* iecoop_query(detail::type_id wanted) noexcept = 0;

 protected:
  interface_base() = default;
  interface_base(const interface_base&) = default;
  interface_base& operator=(const interface_base&) = default;
  ~interface_base() = default;
};

namespace detail {

template <class I>
struct interface_closure;
template <class List>
struct closure_of_list;
template <class... Is>
struct closure_of_list<type_list<Is...>> {
  using type = typename concat<type_list<>, typename interface_closure<Is>::type...>::type;
};
/// An interface and every interface it extends, transitively.
template <class I>
struct interface_closure {
  using type = typename concat<type_list<I>, typename closure_of_list<typename I::iecoop_extended>::type>::type;
};

/// An interface itself (a block implementing one is not: its iecoop_interface names another
/// class, or is ambiguous).
template <class T>
concept is_interface = requires {
  typename T::iecoop_extended;
  requires std::is_same_v<typename T::iecoop_interface, T>;
};

}  // namespace detail

/**
 * The interfaces a block IMPLEMENTS, as the last template argument of its base:
 * `function_block<FB, implements<I_A, I_B>>` is ST's `FUNCTION_BLOCK FB IMPLEMENTS I_A, I_B`,
 * `extends<FB2, FB1, implements<I_C>>` is `FUNCTION_BLOCK FB2 EXTENDS FB1 IMPLEMENTS I_C`.
 * The block must implement every method and property of the interfaces (and of the
 * interfaces they extend); iecoop adds what queries need. A tag, never a base class.
 */
template <class... Interfaces>
struct implements;

namespace detail {

template <class T>
struct is_implements : std::false_type {};
template <class... Is>
struct is_implements<implements<Is...>> : std::true_type {};

/// Every interface block B implements: the ones it declares, those they extend, and those
/// of the blocks it extends (each layer below lists them all).
template <class B>
struct all_interfaces {
  using type = type_list<>;
};
template <class B>
  requires requires { typename B::iecoop_interfaces; }
struct all_interfaces<B> {
  using type = typename B::iecoop_interfaces;
};
template <class B>
using all_interfaces_t = typename all_interfaces<B>::type;

template <class B>
concept queryable = !std::is_same_v<all_interfaces_t<B>, type_list<>>;

template <class I, class Block>
void* query_interface_in(Block* block, type_id wanted) noexcept {
  return wanted == type_id_of<I>() ? static_cast<void*>(static_cast<I*>(block)) : nullptr;
}

/// The answer of block D (the most derived type known) to a query.
template <class D, class... Is>
void* answer_query(D* block, type_id wanted, type_list<Is...>) noexcept {
  if (wanted == type_id_of<any_block>() || wanted == type_id_of<D>()) return static_cast<void*>(block);
  void* found = nullptr;
  ((found == nullptr ? (found = query_interface_in<Is>(block, wanted)) : found), ...);
  if (found != nullptr) return found;
  using base = typename base_of<D>::type;
  if constexpr (!std::is_void_v<base>) {
    return answer_query<base>(static_cast<base*>(block), wanted, type_list<>{});
  } else {
    return nullptr;
  }
}

/// The layer under a block that implements interfaces: Base (the block it extends, or
/// nothing), the interfaces it adds, and the one answer to every query, given as Self — the
/// block being defined, so that queries find it and what it extends.
//
// The interfaces are virtual bases, so that an interface the block reaches along two ways —
// listed and also extended by another listed one, or implemented by the block it extends and
// listed again, or extended by an interface this block adds — is one interface in the block.
template <class Self, class Base, class... Is>
class implementing : public Base, public virtual Is... {
  static_assert((is_interface<Is> && ...),
                "iecoop: implements<I...> lists interfaces (classes derived from interface_base<I>); a block to "
                "extend goes before it: extends<Self, Base, implements<I...>>");

 public:
  using Base::Base;
  using iecoop_interfaces =
      typename concat<typename closure_of_list<type_list<Is...>>::type, all_interfaces_t<Base>>::type;

  void* iecoop_query(type_id wanted) noexcept override {
    return answer_query(static_cast<Self*>(this), wanted, iecoop_interfaces{});
  }
};

template <class List>
struct first_of;
template <class First, class... Rest>
struct first_of<type_list<First, Rest...>> {
  using type = First;
};

/// What a block without a base block stands on: nothing (a type of its own for each block,
/// so that a block and its first member never share an empty base and the member stays at
/// offset 0). Its construction tells a derived block under construction where its bottom
/// level lies (detail/construction.hpp).
template <class Self>
struct no_block {
  constexpr no_block() noexcept {
    if (!std::is_constant_evaluated()) root_constructed(this);
  }
  constexpr no_block(const no_block&) noexcept = default;
  constexpr no_block& operator=(const no_block&) noexcept = default;
};

template <class Self, class Base, class Interfaces>
struct interface_layer {
  static_assert(is_implements<Interfaces>::value,
                "iecoop: the interfaces of a block are given as implements<I...>: "
                "function_block<FB, implements<I_A, I_B>>, extends<FB2, FB1, implements<I_C>>");
};
template <class Self, class Base, class... Is>
struct interface_layer<Self, Base, implements<Is...>> {
  // A layer only where there are interfaces to answer for (a block without any stays free
  // of a vtable).
  using type = std::conditional_t<sizeof...(Is) == 0 && !queryable<Base>, Base, implementing<Self, Base, Is...>>;
};
/// The base of function_block<Self, Interfaces> (Base = no_block<Self>) or of
/// extends<Self, Base, Interfaces>.
template <class Self, class Base, class Interfaces>
using interface_layer_t = typename interface_layer<Self, Base, Interfaces>::type;

}  // namespace detail

/**
 * An interface variable (ST: `x : I;`): a non-owning reference to any block that implements
 * I, 0 until assigned, reassignable at run time. `x->M()` calls the block's method (one
 * virtual call); through an unassigned variable it reports fault_kind::unassigned_interface
 * and, as the call cannot be made, stops the program if the handler returns (a handler that
 * must continue throws or jumps away).
 */
template <class I>
class itf;

namespace detail {
template <class T>
inline constexpr bool is_interface_variable = false;
template <class I>
inline constexpr bool is_interface_variable<itf<I>> = true;
template <class I>
struct is_iec_value<itf<I>> : std::true_type {};

/// A variable of iecoop's (var<>, in_out<> and REFERENCE_TO, retain<>, a PROPERTY, ...), also
/// one whose value only its block may read.
template <class T>
concept any_variable_wrapper = requires { typename std::remove_cvref_t<T>::iecoop_value_wrapper; };

/// A variable wrapper whose value is a block implementing I, reached as the variable itself
/// (a REFERENCE TO FB_X or an in-out of it: `ip := refBlock;`).
template <class I, class W>
concept wraps_implementing_block = value_wrapper<W> && requires(W& w) {
  { w.get() } -> std::same_as<unwrapped_t<W>&>;
  requires std::derived_from<unwrapped_t<W>, I>;
};
}  // namespace detail

template <class I>
class itf {
  static_assert(detail::is_interface<I>,
                "iecoop: itf<I> refers to an interface (a class derived from interface_base<I>)");

 public:
  using interface_type = I;

  constexpr itf() noexcept = default;
  constexpr itf(std::nullptr_t) noexcept {}  // implicit: x := 0
  /// Refers to a block implementing I: `x = fbInstance;`
  template <class T>
    requires(std::derived_from<T, I>)
  constexpr itf(T& block) noexcept : target_(&block) {}  // implicit: ST assigns instances to interface variables
  /// From a REFERENCE TO (or in-out of) a block implementing I: `ip = refBlock;`.
  template <class W>
    requires detail::wraps_implementing_block<I, W>
  constexpr itf(W& reference) : target_(&reference.get()) {}  // implicit: as the block itself
  template <class T>
    requires(!std::derived_from<T, I> && !detail::is_interface_variable<std::remove_cv_t<T>> &&
             !detail::any_variable_wrapper<T>)
  itf(T&) {  // implicit on purpose
    static_assert(detail::dependent_false<T>,
                  "iecoop: this block does not implement the interface; declare it "
                  "`struct FB : function_block<FB, implements<I>>` (or EXTENDS a block that does)");
  }
  /// From a variable of an interface that extends I.
  template <class J>
    requires(std::derived_from<J, I> && !std::is_same_v<J, I>)
  constexpr itf(const itf<J>& other) noexcept : target_(other.get()) {}  // implicit on purpose

  /// The interface of the block referred to; an unassigned variable is a fault.
  I* operator->() const { return &checked(); }
  I& operator*() const { return checked(); }
  [[nodiscard]] constexpr I* get() const noexcept { return target_; }
  explicit constexpr operator bool() const noexcept { return target_ != nullptr; }

  /// `x = 0` / `x <> 0`: a BOOL, as in ST.
  friend constexpr BOOL operator==(const itf& a, std::nullptr_t) noexcept { return BOOL(a.target_ == nullptr); }
  friend constexpr BOOL operator!=(const itf& a, std::nullptr_t) noexcept { return BOOL(a.target_ != nullptr); }
  friend constexpr BOOL operator==(std::nullptr_t, const itf& b) noexcept { return BOOL(b.target_ == nullptr); }
  friend constexpr BOOL operator!=(std::nullptr_t, const itf& b) noexcept { return BOOL(b.target_ != nullptr); }
  /// ST compares an interface variable with the number 0 only; the 0 may also arrive as an
  /// int (a test framework forwarding its operands): equal when both are 0.
  template <std::same_as<int> Zero>
  friend constexpr BOOL operator==(const itf& a, Zero zero) noexcept {
    return BOOL(a.target_ == nullptr && zero == 0);
  }
  template <std::same_as<int> Zero>
  friend constexpr BOOL operator!=(const itf& a, Zero zero) noexcept {
    return BOOL(!(a.target_ == nullptr && zero == 0));
  }
  /// The same block?
  friend constexpr BOOL operator==(const itf& a, const itf& b) noexcept { return BOOL(a.target_ == b.target_); }
  friend constexpr BOOL operator!=(const itf& a, const itf& b) noexcept { return BOOL(a.target_ != b.target_); }

 private:
  I& checked() const {
    if (target_ == nullptr) unassigned();
    return *target_;
  }
  [[noreturn]] static void unassigned() {
    fault(fault_kind::unassigned_interface, "call through an interface variable that is 0 (not assigned)");
    std::abort();
  }

  I* target_ = nullptr;
};

namespace detail {
template <class Block>
void* query_block(Block& block, type_id wanted) noexcept {
  if constexpr (queryable<Block>) {
    using first = typename first_of<all_interfaces_t<Block>>::type;
    return static_cast<first&>(block).iecoop_query(wanted);  // dispatches to the most derived block
  } else {
    return wanted == type_id_of<Block>() || wanted == type_id_of<any_block>() ? static_cast<void*>(&block) : nullptr;
  }
}
}  // namespace detail

/// T implements I (and nothing of I is left abstract): usable where an I is expected, and as
/// a constraint for generic code that calls I's methods on T directly (no virtual dispatch
/// when T, or the method, is final).
template <class T, class I>
concept Implements = detail::is_interface<I> && std::derived_from<T, I> && !std::is_abstract_v<T>;

/**
 * ST's `__QUERYINTERFACE(source, dest)`: if the block behind `source` (an interface variable
 * or a block) implements J, sets dest to it and returns TRUE; otherwise sets dest to 0 and
 * returns FALSE.
 */
template <class J, class I>
BOOL query_interface(const itf<I>& source, itf<J>& dest) noexcept {
  I* const block = source.get();  // first: source and dest may be the same variable
  dest = nullptr;
  if (block == nullptr) return FALSE;
  void* found = block->iecoop_query(detail::type_id_of<J>());
  if (found == nullptr) return FALSE;
  dest = *static_cast<J*>(found);
  return TRUE;
}
template <class J, class Block>
  requires(!detail::is_interface_variable<Block>)
BOOL query_interface(Block& source, itf<J>& dest) noexcept {
  if constexpr (std::derived_from<Block, J>) {
    dest = source;
    return TRUE;
  } else {
    dest = nullptr;
    void* found = detail::query_block(source, detail::type_id_of<J>());
    if (found == nullptr) return FALSE;
    dest = *static_cast<J*>(found);
    return TRUE;
  }
}

/**
 * ST's `__QUERYPOINTER(source, pointer)`: an untyped pointer to the block behind the interface
 * variable (TRUE), or 0 (FALSE) if it is unassigned. As in ST, the caller must know the type;
 * query_pointer<B>(source) checks it.
 */
template <class I>
BOOL query_pointer(const itf<I>& source, void*& pointer) noexcept {
  pointer = source ? source.get()->iecoop_query(detail::type_id_of<detail::any_block>()) : nullptr;
  return BOOL(pointer != nullptr);
}
/// The block behind the interface variable as a B* if it is a B (or derived from B), else nullptr.
template <class B, class I>
B* query_pointer(const itf<I>& source) noexcept {
  if (!source) return nullptr;
  return static_cast<B*>(source.get()->iecoop_query(detail::type_id_of<B>()));
}

}  // namespace iecoop

#include <iecoop/detail/pop_macros.hpp>
