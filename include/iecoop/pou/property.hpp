// SPDX-License-Identifier: MIT
// iecoop/pou/property.hpp — PROPERTY: Get and Set accessors used with the syntax of a variable.
//
//     // PROPERTY PUBLIC prop_iA : INT
//     struct FB_A : function_block<FB_A> {
//       INT iA;
//       INT prop_iA_Get() { return iA; }                  // FB_A.prop_iA.Get:  prop_iA := iA;
//       void prop_iA_Set(INT value) { iA = value; }       // FB_A.prop_iA.Set:  iA := prop_iA;
//       [[no_unique_address]] property<INT, &FB_A::prop_iA_Get, &FB_A::prop_iA_Set> prop_iA{this};
//       void body() { iA = iA + 1; }
//     };
//
//     fbA.prop_iA = 0;                 // calls Set
//     if (fbA.prop_iA > 500) ...       // calls Get
//     iVar = fbA.prop_iA;              // calls Get
//
// A property of interface type (or POINTER_TO, REFERENCE_TO) is gone through with `->`, ST's dot:
// `fbPID.IntegratorBounds->Maximum = 5.0;` calls Get, then the interface's own Maximum Set;
// `fbPID.IntegratorBounds->Reset();` calls Get, then Reset. Of a STRUCT property, `->` reads a
// field of Get's copy (`r = fb.Limits->rHigh;`), which cannot be assigned.
//
// A property holds no data. Declared [[no_unique_address]] — always: it is how the property
// finds its block — it adds no bytes, sits at its owner's own address (GCC and Clang place an
// empty member there, following the Itanium C++ ABI) and compiles to the accessor call. Its
// initializer `{this}` hands it the block under construction, so that it checks that address
// once: a property declared without [[no_unique_address]] is a fault (property_layout) when
// its block is constructed, never a read of other bytes. The accessors are ordinary member
// functions: virtual to be overridable, pure virtual for an ABSTRACT property, final for a
// FINAL one. The property's access modifier is the section it is declared in; an accessor's
// own PRIVATE is the option owner_only_get / owner_only_set (PROTECTED: the same, and derived
// blocks call the protected accessor function). A property without Set is read-only, one
// without Get write-only; the missing direction does not compile.
#pragma once

#include <compare>
#include <cstddef>
#include <cstdlib>
#include <new>
#include <type_traits>
#include <utility>

#include <iecoop/config.hpp>
#include <iecoop/detail/diagnostics.hpp>
#include <iecoop/detail/lifecycle_state.hpp>
#include <iecoop/fault.hpp>
#include <iecoop/types/detail/value_operators.hpp>

#include <iecoop/detail/push_macros.hpp>

#if defined(_MSC_VER) && !defined(__clang__)
#error "iecoop: property<> needs [[no_unique_address]] as GCC and Clang implement it (MSVC ignores the attribute)"
#endif

namespace iecoop {

/// How a watch list shows a property ({attribute 'monitoring' := ...}).
namespace monitoring {
/// 'call' (the default): the watch list calls the Get accessor to show the value.
struct call {};
/// 'variable': every Get and Set also records the value in the block's member `Shadow`, which
/// the watch list shows without calling the accessor.
template <auto Shadow>
struct variable {};
}  // namespace monitoring

/// Restricts one accessor to the block that declares the property (an accessor's PRIVATE):
/// `property<INT, &FB::p_Get, &FB::p_Set, owner_only_set>` can be read anywhere and assigned
/// only inside FB.
struct owner_only_get {};
struct owner_only_set {};

namespace detail {

template <class F>
struct accessor_class {
  using type = void;
};
template <class C, class R, class... P>
struct accessor_class<R (C::*)(P...)> {
  using type = C;
};
template <class C, class R, class... P>
struct accessor_class<R (C::*)(P...) const> {
  using type = C;
};
template <class C, class R, class... P>
struct accessor_class<R (C::*)(P...) noexcept> {
  using type = C;
};
template <class C, class R, class... P>
struct accessor_class<R (C::*)(P...) const noexcept> {
  using type = C;
};

template <auto Get, auto Set>
using property_owner =
    std::conditional_t<std::is_same_v<decltype(Get), std::nullptr_t>, typename accessor_class<decltype(Set)>::type,
                       typename accessor_class<decltype(Get)>::type>;

template <class Option, class... Options>
inline constexpr bool has_option = (std::is_same_v<Option, Options> || ...);

template <class Option>
struct is_monitoring_option : std::false_type {};
template <>
struct is_monitoring_option<monitoring::call> : std::true_type {};
template <auto Shadow>
struct is_monitoring_option<monitoring::variable<Shadow>> : std::true_type {};
/// The options property<> knows.
template <class Option>
inline constexpr bool is_property_option =
    std::is_same_v<Option, owner_only_get> || std::is_same_v<Option, owner_only_set> ||
    is_monitoring_option<Option>::value;

template <class... Options>
struct monitoring_of {
  using type = monitoring::call;
};
template <auto Shadow, class... Rest>
struct monitoring_of<monitoring::variable<Shadow>, Rest...> {
  using type = monitoring::variable<Shadow>;
};
template <class First, class... Rest>
struct monitoring_of<First, Rest...> : monitoring_of<Rest...> {};

/// iecoop_value_wrapper of a property only its block may read (not a value wrapper).
struct property_read_by_owner_only {};

/// A value of T converts to U implicitly and without narrowing (a REAL property reads as
/// LREAL, not as int).
template <class T, class U>
concept widens_to = !std::is_same_v<U, T> && std::is_convertible_v<const T&, U> && requires(const T& t) { U{t}; };

/// A value with a `->` of its own: an interface variable (itf<I>), a POINTER_TO, a REFERENCE_TO.
template <class T>
concept has_arrow = requires(const T& value) { value.operator->(); };

/// What `fb.Prop->field` reaches for a property of a STRUCT type: the fields of the copy Get
/// gave, read-only (assigning a field of a copy would change nothing), for the rest of the
/// statement.
template <class T>
class property_value_copy {
 public:
  explicit constexpr property_value_copy(const T& value) : value_(value) {}
  constexpr const T* operator->() const noexcept { return &value_; }

 private:
  T value_;
};

}  // namespace detail

/**
 * A PROPERTY of type T with accessors `Get` (a member function returning T, or nullptr for
 * a write-only property) and `Set` (a member function taking T, or nullptr for a read-only
 * one). Declare it `[[no_unique_address]] property<...> Name{this};`. Options: owner_only_get, owner_only_set,
 * monitoring::variable<&Owner::shadow>.
 */
template <class T, auto Get, auto Set = nullptr, class... Options>
class property {
  static_assert(!std::is_same_v<decltype(Get), std::nullptr_t> || !std::is_same_v<decltype(Set), std::nullptr_t>,
                "iecoop: a property needs a Get or a Set accessor (or both)");
  static_assert(!std::is_void_v<detail::property_owner<Get, Set>>,
                "iecoop: a property's accessors are member functions of its block; write "
                "property<T, &FB::Name_Get, &FB::Name_Set> (nullptr for a missing one)");
  static_assert(std::is_same_v<decltype(Get), std::nullptr_t> || std::is_same_v<decltype(Set), std::nullptr_t> ||
                    std::is_same_v<typename detail::accessor_class<decltype(Get)>::type,
                                   typename detail::accessor_class<decltype(Set)>::type>,
                "iecoop: a property's Get and Set accessors belong to the same block; declare both (or "
                "overrides of both) in the block that declares the property");
  static_assert((detail::is_property_option<Options> && ...),
                "iecoop: a property's options are owner_only_get, owner_only_set, monitoring::call and "
                "monitoring::variable<&FB::shadow>; check the spelling of the others");
  static_assert((std::size_t{0} + ... + (detail::is_monitoring_option<Options>::value ? 1 : 0)) <= 1,
                "iecoop: a property has one monitoring mode ({attribute 'monitoring'}): monitoring::call or "
                "monitoring::variable<&FB::shadow>, not both");
  static constexpr bool owner_get = detail::has_option<owner_only_get, Options...>;
  static constexpr bool owner_set = detail::has_option<owner_only_set, Options...>;
  static constexpr bool open = !owner_get && !owner_set;

 public:
  using value_type = T;
  /// In expressions, its value (detail/value_operators.hpp); a property only its block may
  /// read opts out, so that the value's own operators apply inside the block.
  using iecoop_value_wrapper = std::conditional_t<owner_get, detail::property_read_by_owner_only, void>;
  using owner_type = detail::property_owner<Get, Set>;
  using monitoring_mode = typename detail::monitoring_of<Options...>::type;
  static constexpr bool readable = !std::is_same_v<decltype(Get), std::nullptr_t>;
  static constexpr bool writable = !std::is_same_v<decltype(Set), std::nullptr_t>;

  /// `[[no_unique_address]] property<...> Name{this};` — the block (or interface, program,
  /// list of global variables) under construction, whose address the property must share.
  template <class Block>
    requires std::is_convertible_v<Block*, owner_type*>
  constexpr explicit property(Block* block) noexcept {
    if (!std::is_constant_evaluated()) {
      if (static_cast<const void*>(this) != static_cast<const void*>(static_cast<owner_type*>(block))) misplaced();
    }
  }
  /// Without `{this}` a property could not check where it is.
  template <class Self = property>
  constexpr property() noexcept {
    static_assert(detail::dependent_false<Self>,
                  "iecoop: a property is declared `[[no_unique_address]] property<T, &FB::Name_Get, &FB::Name_Set> "
                  "Name{this};` — the initializer {this} lets it check that it sits at its block's address");
  }

  // Reading through a non-const block calls Get on it; through a const block, a const Get
  // (`T Name_Get() const`) is called as const (see read() const).

  /// Reading the property calls Get (`iVar = fbA.prop_iA;`).
  operator T()  // implicit: reads as the variable
    requires(!owner_get)
  {
    return read();
  }
  operator T() const  // implicit on purpose
    requires(!owner_get)
  {
    return read();
  }
  /// ... also where T converts on without narrowing (`LREAL x = fb.rProp;` for a REAL property).
  template <class U>
    requires(!owner_get && detail::widens_to<T, U>)
  operator U() {  // implicit on purpose
    return read();
  }
  template <class U>
    requires(!owner_get && detail::widens_to<T, U>)
  operator U() const {  // implicit on purpose
    return read();
  }
  /// `IF fb.bProp THEN`
  explicit operator bool()
    requires(!owner_get && std::is_constructible_v<bool, const T&>)
  {
    return static_cast<bool>(read());
  }
  explicit operator bool() const
    requires(!owner_get && std::is_constructible_v<bool, const T&>)
  {
    return static_cast<bool>(read());
  }
  /// Assigning the property calls Set (`fbA.prop_iA = 0;`).
  property& operator=(const T& value)
    requires(!owner_set)
  {
    write(value);
    return *this;
  }
  /// `fbA.prop = fbB.prop` calls fbB's Get, then fbA's Set.
  property& operator=(property& other)
    requires open
  {
    write(other.read());
    return *this;
  }
  /// From a variable wrapper (or property) of another type whose value converts implicitly
  /// (`fb.dProp = iVar;` with a var<INT> into a DINT property).
  template <class V>
    requires(!owner_set && detail::converts_through_wrapper<T, V>)
  property& operator=(const V& other) {
    const T value = detail::value_of(other);
    write(value);
    return *this;
  }
  /// A value of a type that ST converts only explicitly: rejected, naming the conversion.
  template <class V>
    requires(!owner_set && detail::rejected_value<T, V>)
  void operator=(const V&) {
    detail::reject_value<T, V>();
  }

  /// ST's `fb.Prop.Member`: the member of what Get gives. Through a property of interface
  /// type (or POINTER_TO, REFERENCE_TO) it reaches the block behind it, as the interface
  /// variable does: `fbPID.IntegratorBounds->Maximum = 5.0;` calls IntegratorBounds' Get, then
  /// the interface's own Maximum Set; `fbPID.IntegratorBounds->Reset();` calls Reset; an
  /// interface that is 0 is a fault (fault_kind::unassigned_interface). Of a STRUCT property it
  /// reads a field of the value (`x = fb.Position->x;`); the fields are read-only, as the value
  /// is a copy: assign the whole property to change it.
  auto operator->()
    requires(!owner_get && std::is_class_v<T>)
  {
    return arrow(*this);
  }
  auto operator->() const
    requires(!owner_get && std::is_class_v<T>)
  {
    return arrow(*this);
  }

  /// What reading the property gives (its Get accessor).
  [[nodiscard]] T get()
    requires(!owner_get)
  {
    return read();
  }
  [[nodiscard]] T get() const
    requires(!owner_get)
  {
    return read();
  }
  /// What assigning the property does (its Set accessor).
  void set(const T& value)
    requires(!owner_set)
  {
    write(value);
  }

  /// The value a watch list shows: the value last recorded by Get or Set ('variable'), or a
  /// call of Get ('call', which runs whatever the accessor does).
  [[nodiscard]] T monitor()
    requires(readable || !std::is_same_v<monitoring_mode, monitoring::call>)
  {
    if constexpr (std::is_same_v<monitoring_mode, monitoring::call>) {
      return read();
    } else {
      return shadow_ref();
    }
  }
  [[nodiscard]] T monitor() const
    requires(readable || !std::is_same_v<monitoring_mode, monitoring::call>)
  {
    if constexpr (std::is_same_v<monitoring_mode, monitoring::call>) {
      return read();
    } else {
      return shadow_ref();
    }
  }

 private:
  friend owner_type;

  // Only the owner copies its properties, when the block itself is copied. A property has no
  // variables, so constructing a copy does nothing and calls no accessor. Anywhere else a
  // copy would be a property without its block: `auto x = fb.prop;` does not compile; write
  // `INT x = fb.prop;` or `auto x = fb.prop.get();` (inside the block too, where C++ cannot
  // stop `auto`).
  constexpr property(const property&) noexcept = default;
  // Assigning from a const property (the block's own `p = other.p` with a const `other`, or
  // the whole block assigned, ST's `fbA := fbB`) calls the other's Get and this one's Set, as
  // `fbA.p = fbB.p` does. An online change copies the block without calling accessors.
  property& operator=(const property& other) {
    if (&other != this && !detail::current_lifecycle.relocating) {
      if constexpr (readable && writable) write(other.read());
    }
    return *this;
  }

  // The accessors for the owner only (owner_only_get / owner_only_set).
  operator T()  // implicit on purpose
    requires(owner_get)
  {
    return read();
  }
  operator T() const  // implicit on purpose
    requires(owner_get)
  {
    return read();
  }
  // In the block's own expressions: `Gain.get() * 2.0` (C++ applies no conversion to the
  // operand of an operator template, and the generic wrapper operators must not read it).
  [[nodiscard]] T get()
    requires(owner_get)
  {
    return read();
  }
  [[nodiscard]] T get() const
    requires(owner_get)
  {
    return read();
  }
  auto operator->()
    requires(owner_get && std::is_class_v<T>)
  {
    return arrow(*this);
  }
  auto operator->() const
    requires(owner_get && std::is_class_v<T>)
  {
    return arrow(*this);
  }
  property& operator=(const T& value)
    requires(owner_set)
  {
    write(value);
    return *this;
  }
  property& operator=(property& other)
    requires(!open)
  {
    write(other.read());
    return *this;
  }

  static constexpr void check_readable() {
    static_assert(readable, "iecoop: the property has no Get accessor (it is write-only); it cannot be read");
    if constexpr (readable) {
      static_assert(std::is_convertible_v<std::invoke_result_t<decltype(Get), owner_type&>, T>,
                    "iecoop: a property's Get accessor returns the property's type; declare it `T Name_Get()`");
    }
  }

  // `->`: Get's value, through which C++ applies the value's own `->` next (an interface
  // variable, a pointer, a reference), or a read-only copy of a STRUCT.
  template <class Self>
  static auto arrow(Self& self) {
    static_assert(readable,
                  "iecoop: `fb.Prop->Member` reaches the member through the value the property's Get gives, and "
                  "this property has no Get (it is write-only); give the property a Get accessor, or assign "
                  "the whole property (`fb.Prop = value;`)");
    static_assert(detail::has_arrow<T> || !detail::is_iec_value<T>::value,
                  "iecoop: `fb.Prop->Member` reaches into a property of interface, POINTER_TO, REFERENCE_TO or "
                  "STRUCT type; a value of this type has no members: read the property as a value");
    if constexpr (!readable) {
      // (Refused above; what is returned only keeps the compiler from adding errors.)
      if constexpr (detail::has_arrow<T> && std::is_default_constructible_v<T>) {
        return T{};
      } else {
        return static_cast<const T*>(nullptr);
      }
    } else if constexpr (detail::has_arrow<T>) {
      return self.read();  // C++ applies T's own operator-> next (an unassigned interface faults there)
    } else {
      return detail::property_value_copy<T>(self.read());
    }
  }

  T read() {
    check_readable();
    if constexpr (readable) {
      const T value = (owner().*Get)();
      record(value);
      return value;
    } else {
      return T{};
    }
  }
  // Reading through a const block: a const Get is called as such (and not recorded for
  // monitoring); a non-const Get — the usual kind, as ST has no const — on the same block,
  // which must then not be an object defined const (`const FB fb;` needs const accessors).
  T read() const {
    check_readable();
    if constexpr (readable) {
      if constexpr (std::is_invocable_v<decltype(Get), const owner_type&>) {
        return (owner().*Get)();
      } else {
        return const_cast<property&>(*this).read();
      }
    } else {
      return T{};
    }
  }

  void write(const T& value) {
    static_assert(writable, "iecoop: the property has no Set accessor (it is read-only); it cannot be assigned");
    if constexpr (writable) {
      static_assert(std::is_invocable_v<decltype(Set), owner_type&, const T&>,
                    "iecoop: a property's Set accessor takes the property's type; declare it `void Name_Set(T value)`");
      record(value);
      (owner().*Set)(value);
    }
  }

  [[noreturn]] static void misplaced() {
    fault(fault_kind::property_layout,
          "a property is not at its block's address: declare it [[no_unique_address]] (GCC or Clang); it cannot "
          "reach its block");
    std::abort();
  }

  // The property is an empty member at offset 0 of its owner, so the owner lives at its
  // address (checked when the owner is constructed; see docs/design.md, "Properties").
  owner_type& owner() noexcept { return *std::launder(reinterpret_cast<owner_type*>(this)); }
  const owner_type& owner() const noexcept { return *std::launder(reinterpret_cast<const owner_type*>(this)); }

  void record(const T& value) {
    if constexpr (!std::is_same_v<monitoring_mode, monitoring::call>) {
      shadow_ref() = value;
    }
  }
  template <auto Shadow>
  static constexpr auto shadow_member(monitoring::variable<Shadow>) {
    return Shadow;
  }
  auto& shadow_ref() { return owner().*shadow_member(monitoring_mode{}); }
  const auto& shadow_ref() const { return owner().*shadow_member(monitoring_mode{}); }
};

namespace detail {
template <class P>
struct is_property : std::false_type {};
template <class T, auto G, auto S, class... O>
struct is_property<property<T, G, S, O...>> : std::true_type {};
}  // namespace detail

/// A PROPERTY (for watch lists and traces: `p.monitor()` shows its value per its monitoring mode).
template <class P>
concept Property = detail::is_property<std::remove_cvref_t<P>>::value;

}  // namespace iecoop

#include <iecoop/detail/pop_macros.hpp>
