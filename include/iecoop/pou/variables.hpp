// SPDX-License-Identifier: MIT
// iecoop/pou/variables.hpp — variable sections whose rules C++ members do not have by themselves:
//   local<T, Owner>  VAR of a block: read from outside (as CODESYS allows), written by the
//                    block and the blocks that extend it — write `var<T>` inside a block
//   read_only<T, Owner>  a variable only Owner writes (the standard blocks' VAR_OUTPUT)
//   in_out<T>        VAR_IN_OUT: a reference bound at the call; using it unbound is a fault
//   output<T>        VAR_OUTPUT of a METHOD or FUNCTION: `"x"_ >> y` copies it out after the call
//   temp<T>          VAR of a METHOD or FUNCTION, beside its inputs: not passed by callers
//
// VAR_INPUT and the VAR_OUTPUT of blocks and programs are plain members.
#pragma once

#include <concepts>
#include <cstdlib>
#include <type_traits>
#include <utility>

#include <iecoop/config.hpp>
#include <iecoop/detail/lifecycle_state.hpp>
#include <iecoop/detail/scalar_access.hpp>
#include <iecoop/fault.hpp>
#include <iecoop/types/array.hpp>
#include <iecoop/types/detail/initial_value.hpp>
#include <iecoop/types/detail/value_operators.hpp>

#include <iecoop/detail/push_macros.hpp>

namespace iecoop {

template <class T, class Owner>
class local;
template <class T, class Owner>
class read_only;
template <class T>
class in_out;

namespace detail {

/// iecoop's own write access to a read_only<> variable: the target of `"Q"_ >> Q` in a call
/// inside its block.
struct read_only_access {
  template <class T, class Owner>
  static constexpr T& ref(read_only<T, Owner>& variable) noexcept {
    return variable.ref();
  }
};

template <class T>
struct is_local : std::false_type {};
template <class T, class O>
struct is_local<local<T, O>> : std::true_type {};
template <class T>
struct is_read_only : std::false_type {};
template <class T, class O>
struct is_read_only<read_only<T, O>> : std::true_type {};
template <class T>
struct is_in_out : std::false_type {};
template <class T>
struct is_in_out<in_out<T>> : std::true_type {};

/// The variable `=>` writes into: a local's or in-out's value, or the variable itself.
template <class Target>
constexpr auto& output_target(Target& target) {
  if constexpr (is_local<Target>::value) {
    return target.ref();
  } else if constexpr (is_read_only<Target>::value) {
    return read_only_access::ref(target);
  } else if constexpr (is_in_out<Target>::value) {
    return target.get();
  } else {
    return target;
  }
}

/// Copies an output to the variable after `=>`, with IEC's implicit conversions.
template <class Target, class V>
constexpr void deliver_output(Target& target, const V& value) {
  auto& variable = output_target(target);
  static_assert(std::is_assignable_v<decltype(variable), const V&>,
                "iecoop: the output does not convert to the variable after =>; give the variable the output's type");
  assign_value(variable, value);
}

}  // namespace detail

namespace detail {

/// What a variable of iecoop's (local<>, read_only<>, temp<>, retain<>) is to its readers:
/// its value, with the operations of its type. With `Open`, everyone also has write access to
/// its parts (`ref()`, `a[i] = x`, `s->x = 1`); assigning the whole is up to the derived class.
template <class T, bool Open>
class variable_value : public condition_conversion<variable_value<T, Open>, T>,
                       public widening_conversion<variable_value<T, Open>, T> {
 public:
  using value_type = T;
  using iecoop_value_wrapper = void;  // in expressions, its value (detail/value_operators.hpp)

  constexpr operator const T&() const noexcept { return value_; }  // implicit: reads as the variable
  [[nodiscard]] constexpr const T& get() const noexcept { return value_; }
  /// `pos->x` for a STRUCT, `ip->M()` for an interface variable.
  constexpr decltype(auto) operator->() const noexcept { return arrow_of(value_); }
  constexpr decltype(auto) operator->() noexcept
    requires Open
  {
    return arrow_of(value_);
  }
  /// An element of an ARRAY (`a[i]`).
  template <class I>
  constexpr decltype(auto) operator[](I&& index) const
    requires requires(const T& v) { v[std::forward<I>(index)]; }
  {
    return value_[std::forward<I>(index)];
  }
  template <class I>
  constexpr decltype(auto) operator[](I&& index)
    requires(Open && requires(T& v) { v[std::forward<I>(index)]; })
  {
    return value_[std::forward<I>(index)];
  }
  /// An element `a[i, j]` of a multi-dimensional ARRAY: `a(i, j)`.
  template <class... I>
  constexpr decltype(auto) operator()(const I&... index) const
    requires requires(const T& v) {
      typename T::iecoop_array;
      v(index...);
    }
  {
    return value_(index...);
  }
  template <class... I>
  constexpr decltype(auto) operator()(const I&... index)
    requires(Open &&
             requires(T& v) {
               typename T::iecoop_array;
               v(index...);
             })
  {
    return value_(index...);
  }
  /// The variable itself: for members of a structured variable (`pos.ref().x = 1;`) and to
  /// bind a VAR_IN_OUT to it.
  [[nodiscard]] constexpr T& ref() noexcept
    requires Open
  {
    return value_;
  }

 protected:
  /// A variable of an enumeration starts through its wrapper's own constructor (local<>,
  /// read_only<>, temp<>, retain<>, persistent<>), which refuses an unknown start one step
  /// from the user's line; were one to default here, initial_value would refuse it.
  constexpr variable_value() = default;
  constexpr explicit variable_value(const T& initial) : value_(initial) {}

  // Values are copied as scalars (detail/scalar_access.hpp), so that the optimiser sees
  // plain loads and stores.
  constexpr void assign(const T& value) { copy_value(value_, value); }
  template <class V>
  constexpr void assign_converted(const V& other) {
    assign_value(value_, value_of(other));
  }
  [[nodiscard]] constexpr T& storage() noexcept { return value_; }

 private:
  T value_ = initial_value<T>();
};

/// A variable everyone may assign (local<>, temp<>, retain<>, persistent<>), with ST's
/// conversions; Derived is the variable's own type, which `using base::operator=;` (C++ hides a
/// base's assignments behind the implicit copy assignment).
template <class Derived, class T>
class assignable_variable : public variable_value<T, true> {
  using base = variable_value<T, true>;

 public:
  /// A non-template operand, so that constants convert as in any assignment (`count = 5;`,
  /// checked while compiling). Compound assignments (`count += 1;`) are those of every
  /// variable wrapper (detail/value_operators.hpp).
  constexpr Derived& operator=(const T& value) {
    this->assign(value);
    return static_cast<Derived&>(*this);
  }
  /// From another variable wrapper whose value converts implicitly (`dOut = i;` with a
  /// var<INT> i into a var<DINT>).
  template <class V>
    requires converts_through_wrapper<T, V>
  constexpr Derived& operator=(const V& other) {
    this->assign_converted(other);
    return static_cast<Derived&>(*this);
  }
  /// A value of a type that ST converts only explicitly: rejected, naming the conversion.
  template <class V>
    requires rejected_value<T, V>
  constexpr void operator=(const V&) {
    reject_value<T, V>();
  }

 protected:
  using base::base;
  constexpr assignable_variable() = default;
};

}  // namespace detail

/**
 * A block's local variable (VAR ... END_VAR): `var<INT> count{5};` inside the block.
 *
 * Read like its value everywhere (`fb.count`, `fb.count + 1`), as CODESYS lets outside code
 * read a block's locals; assigned in the block that declares it and in every block that
 * EXTENDS it (`count = count + 1;`), with the implicit conversions of ST (a var<INT> into a
 * var<DINT>, a STRING into a shorter one). CODESYS also rejects writing a block's local from
 * outside the block; C++ cannot tell a derived block's code from outside code, so iecoop-check
 * checks that rule (docs/iecoop-check.md). A variable that only its own block may write,
 * whoever reads it, is a read_only<T, Owner>.
 */
template <class T, class Owner>
class local : public detail::assignable_variable<local<T, Owner>, T> {
  using base = detail::assignable_variable<local<T, Owner>, T>;

 public:
  /// The block that declares the variable.
  using owner_type = Owner;

  constexpr local()
    requires(!std::is_enum_v<T>)
  = default;
  /// A variable of an enumeration declared without an initial value: its start, or refused
  /// here where iecoop does not know it, so that the report names the declaration's own line.
  constexpr local() noexcept
    requires(std::is_enum_v<T>)
      : base(detail::enum_start_or_zero<T>()) {
    detail::refuse_unknown_enum_start<T>();
  }
  /// The declaration's initial value: `var<INT> count{5};`
  constexpr explicit local(const T& initial) : base(initial) {}
  constexpr local(const local&) = default;
  /// ST's `a := b` between two locals of the same type.
  constexpr local& operator=(const local&) = default;
  using base::operator=;
};

/**
 * A variable only the block `Owner` writes, read by everyone: the VAR_OUTPUT of the standard
 * blocks (`tmr.Q` is read, never assigned, from outside, as in ST). Owner assigns it like any
 * variable, and a call's `"Q"_ >> x` inside Owner delivers into it. Blocks derived from Owner
 * cannot write it (a C++ friend is not inherited): use var<T> for what they write.
 */
template <class T, class Owner>
class read_only : public detail::variable_value<T, false> {
  using base = detail::variable_value<T, false>;

 public:
  /// The block that writes the variable.
  using owner_type = Owner;
  using iecoop_owner_writes = void;

  constexpr read_only()
    requires(!std::is_enum_v<T>)
  = default;
  /// A variable of an enumeration declared without an initial value: its start, or refused
  /// here where iecoop does not know it, so that the report names the declaration's own line.
  constexpr read_only() noexcept
    requires(std::is_enum_v<T>)
      : base(detail::enum_start_or_zero<T>()) {
    detail::refuse_unknown_enum_start<T>();
  }
  constexpr explicit read_only(const T& initial) : base(initial) {}
  constexpr read_only(const read_only&) = default;

 private:
  friend Owner;
  friend struct detail::read_only_access;

  constexpr read_only& operator=(const read_only&) = default;  // Owner's own copies (online change)
  constexpr read_only& operator=(const T& value) {
    this->assign(value);
    return *this;
  }
  template <class V>
    requires detail::converts_through_wrapper<T, V>
  constexpr read_only& operator=(const V& other) {
    this->assign_converted(other);
    return *this;
  }
  /// Write access for the owner, for members of structured variables: `pos.ref().x = 1;`
  [[nodiscard]] constexpr T& ref() noexcept { return this->storage(); }
  // The owner's compound assignments (those of detail/value_operators.hpp are for everyone).
  constexpr read_only& operator+=(const T& v) { return *this = this->get() + v; }
  constexpr read_only& operator-=(const T& v) { return *this = this->get() - v; }
  constexpr read_only& operator++() { return *this = this->get() + T(1); }
  constexpr read_only& operator--() { return *this = this->get() - T(1); }
};

/**
 * VAR_IN_OUT: a reference to the caller's variable, bound at the call (`"x"_ = var`, or
 * `fb.x.bind(var)`), read and written through like the variable itself.
 *
 * Reading or writing it while unbound reports fault_kind::unbound_in_out (and then works on
 * a scratch variable, so nothing undefined happens); calling a block whose VAR_IN_OUT is
 * unbound reports the same fault and skips the body. Assigning one in-out to another copies
 * the value, as ST's `a := b` does; each keeps its binding (also when an online change copies
 * the block). `in_out<const T>` is VAR_IN_OUT CONSTANT.
 */
template <class T>
class in_out : public detail::condition_conversion<in_out<T>, std::remove_const_t<T>>,
               public detail::widening_conversion<in_out<T>, std::remove_const_t<T>> {
 public:
  using value_type = std::remove_const_t<T>;
  using iecoop_value_wrapper = void;

  constexpr in_out() noexcept = default;
  constexpr explicit in_out(T& variable) noexcept : target_(&variable) {}
  constexpr in_out(const in_out&) noexcept = default;

  /// Binds to `variable` (ST: `x := variable` in the call; REF= for references).
  constexpr void bind(T& variable) noexcept { target_ = &variable; }
  /// Binds to the variable inside a wrapper: a block's var<>, a retain<>, or the variable
  /// another in-out refers to.
  template <class W>
    requires requires(W& w) {
      { w.ref() } -> std::convertible_to<T&>;
    }
  constexpr void bind(W& wrapper) noexcept {
    target_ = &static_cast<T&>(wrapper.ref());
  }
  template <class U>
    requires std::is_convertible_v<U&, T&>
  constexpr void bind(const in_out<U>& other) {
    target_ = &static_cast<T&>(other.get());
  }
  /// TRUE once bound (ST: __ISVALIDREF).
  [[nodiscard]] constexpr bool bound() const noexcept { return target_ != nullptr; }

  [[nodiscard]] constexpr T& get() const {
    if (target_ == nullptr) return unbound();
    return *target_;
  }
  constexpr operator T&() const { return get(); }  // implicit: reads as the variable
  /// `r->x` for a STRUCT, `ip->M()` for an interface variable.
  constexpr decltype(auto) operator->() const { return detail::arrow_of(get()); }
  /// An element of an ARRAY (`a[i]`).
  template <class I>
  constexpr decltype(auto) operator[](I&& index) const
    requires requires(T& v) { v[std::forward<I>(index)]; }
  {
    return get()[std::forward<I>(index)];
  }
  /// An element `a[i, j]` of a multi-dimensional ARRAY: `a(i, j)`.
  template <class... I>
  constexpr decltype(auto) operator()(const I&... index) const
    requires requires(T& v) {
      typename value_type::iecoop_array;
      v(index...);
    }
  {
    return get()(index...);
  }

  /// Writes through to the bound variable (a non-template operand, so that constants
  /// convert as in any assignment).
  constexpr const in_out& operator=(const value_type& value) const
    requires(!std::is_const_v<T>)
  {
    detail::copy_value(get(), value);
    return *this;
  }
  /// From another variable wrapper whose value converts implicitly.
  template <class V>
    requires(!std::is_const_v<T> && detail::converts_through_wrapper<value_type, V> &&
             !std::is_same_v<std::remove_cvref_t<V>, in_out>)
  constexpr const in_out& operator=(const V& other) const {
    detail::assign_value(get(), detail::value_of(other));
    return *this;
  }
  /// A value of a type that ST converts only explicitly: rejected, naming the conversion.
  template <class V>
    requires detail::rejected_value<value_type, V>
  constexpr void operator=(const V&) const {
    detail::reject_value<value_type, V>();
  }
  /// ST's `a := b`: copies b's value into a's variable. While an online change copies the
  /// block that holds it, nothing happens: the new instance keeps its own binding.
  constexpr in_out& operator=(const in_out& other) {
    if constexpr (!std::is_const_v<T>) {
      if (!detail::current_lifecycle.relocating) detail::copy_value(get(), other.get());
    }
    return *this;
  }

 private:
  static T& unbound() {
    fault(fault_kind::unbound_in_out, "VAR_IN_OUT used before it was bound to a variable");
    if constexpr (std::is_default_constructible_v<value_type> && std::is_copy_assignable_v<value_type>) {
      static value_type scratch = detail::stand_in_value<value_type>();
      detail::refresh_stand_in(scratch);
      return scratch;
    } else {
      // No stand-in can be made for this type (an abstract block, a block with FB_Init
      // parameters): the program cannot go on.
      std::abort();
    }
  }

  T* target_ = nullptr;
};

/**
 * A VAR_IN_OUT `ARRAY[*] OF T` (one `'*'` per dimension, `ARRAY[*, *]` is ARRAY<T, '*', '*'>):
 * binds to an ARRAY of any bounds with that many dimensions and element type, and takes its
 * bounds with it — LOWER_BOUND and UPPER_BOUND read them, indices are checked against them.
 * A FUNCTION with positional parameters takes one directly: `SUM(in_out<ARRAY<INT, '*'>> a)`
 * is called `SUM(aValues)`.
 */
template <array_check Check, class T, auto... Stars>
  requires detail::array_shape<Stars...>::star
class in_out<basic_array<Check, T, Stars...>> {
  static constexpr std::size_t rank_ = sizeof...(Stars);
  template <array_check C, auto... B>
  static constexpr bool fits = detail::array_shape<B...>::rank == rank_ && !detail::array_shape<B...>::star;

 public:
  using value_type = T;
  static constexpr std::size_t rank = rank_;

  constexpr in_out() noexcept = default;
  /// Bound to `array` (implicit, so that a function's ARRAY[*] parameter takes an ARRAY).
  template <array_check C, auto... B>
    requires fits<C, B...>
  constexpr in_out(basic_array<C, T, B...>& array) noexcept {  // implicit: a parameter takes its ARRAY
    bind(array);
  }
  /// Bound to `array` (ST: the in-out's argument in the call).
  template <array_check C, auto... B>
    requires fits<C, B...>
  constexpr void bind(basic_array<C, T, B...>& array) noexcept {
    elements_ = array.data();
    for (std::size_t d = 0; d < rank_; ++d) {
      lower_[d] = array.lower(d + 1);
      extent_[d] = array.upper(d + 1) - array.lower(d + 1) + 1;
    }
  }
  /// Bound to the ARRAY inside a variable wrapper or another in-out.
  template <class W>
    requires requires(W& w) { w.ref(); }
  constexpr void bind(W& wrapper) noexcept {
    bind(wrapper.ref());
  }
  constexpr void bind(const in_out& other) noexcept { *this = other; }
  template <array_check C, auto... B>
    requires fits<C, B...>
  constexpr void bind(const in_out<basic_array<C, T, B...>>& other) {
    bind(other.get());
  }
  /// TRUE once bound (ST: __ISVALIDREF).
  [[nodiscard]] constexpr bool bound() const noexcept { return elements_ != nullptr; }

  /// The lower bound of dimension `d` (from 1); see LOWER_BOUND.
  [[nodiscard]] constexpr detail::array_index lower(std::size_t d) const noexcept { return lower_[d - 1]; }
  /// The upper bound of dimension `d` (from 1); see UPPER_BOUND.
  [[nodiscard]] constexpr detail::array_index upper(std::size_t d) const noexcept {
    return lower_[d - 1] + extent_[d - 1] - 1;
  }
  /// The number of elements.
  [[nodiscard]] constexpr std::size_t size() const noexcept {
    std::size_t n = elements_ != nullptr ? 1 : 0;
    for (std::size_t d = 0; d < rank_; ++d) n *= static_cast<std::size_t>(extent_[d]);
    return n;
  }

  /// A one-dimensional ARRAY's element `a[i]`.
  template <class I>
    requires(rank_ == 1)
  [[nodiscard]] constexpr T& operator[](const I& index) const {
    return (*this)(index);
  }
  /// The element `a[i, j, ...]` of ST: one index per dimension.
  template <class... I>
  [[nodiscard]] constexpr T& operator()(const I&... index) const {
    static_assert(sizeof...(I) == rank_, "iecoop: index an ARRAY with one index per dimension, a(i, j) for a[i, j]");
    (detail::check_index_type<I>(), ...);
    if (elements_ == nullptr) return unbound();
    std::size_t offset = 0;
    std::size_t d = 0;
    ((offset = offset * static_cast<std::size_t>(extent_[d]) +
               detail::offset_in<Check>(detail::index_value(index), lower_[d], extent_[d]),
      ++d),
     ...);
    return elements_[offset];
  }
  /// The elements in memory order, for range-for.
  [[nodiscard]] constexpr T* begin() const noexcept { return elements_; }
  [[nodiscard]] constexpr T* end() const noexcept { return elements_ + size(); }

 private:
  static T& unbound() {
    fault(fault_kind::unbound_in_out, "VAR_IN_OUT ARRAY[*] used before it was bound to an ARRAY");
    static T scratch = detail::stand_in_value<T>();
    detail::refresh_stand_in(scratch);
    return scratch;
  }

  T* elements_ = nullptr;
  detail::array_index lower_[rank_]{};
  detail::array_index extent_[rank_]{};
};

/// ST's `LOWER_BOUND(a, dim)` of an ARRAY[*] in-out: its bound at run time, a DINT.
template <array_check Check, class T, auto... Stars>
[[nodiscard]] constexpr DINT LOWER_BOUND(const in_out<basic_array<Check, T, Stars...>>& a,
                                         std::type_identity_t<array_dimension<sizeof...(Stars)>> dim) noexcept {
  return DINT(static_cast<std::int32_t>(a.lower(dim.value)));
}
/// ST's `UPPER_BOUND(a, dim)` of an ARRAY[*] in-out: its bound at run time, a DINT.
template <array_check Check, class T, auto... Stars>
[[nodiscard]] constexpr DINT UPPER_BOUND(const in_out<basic_array<Check, T, Stars...>>& a,
                                         std::type_identity_t<array_dimension<sizeof...(Stars)>> dim) noexcept {
  return DINT(static_cast<std::int32_t>(a.upper(dim.value)));
}

/// LOWER_BOUND and UPPER_BOUND of an ARRAY held by a variable wrapper (var<>, in_out<>, retain<>, ...).
template <detail::value_wrapper W>
  requires requires { typename detail::unwrapped_t<W>::iecoop_array; }
[[nodiscard]] constexpr DINT LOWER_BOUND(const W&, array_dimension<detail::unwrapped_t<W>::rank> dim) noexcept {
  return DINT(static_cast<std::int32_t>(detail::unwrapped_t<W>::lower(dim.value)));
}
template <detail::value_wrapper W>
  requires requires { typename detail::unwrapped_t<W>::iecoop_array; }
[[nodiscard]] constexpr DINT UPPER_BOUND(const W&, array_dimension<detail::unwrapped_t<W>::rank> dim) noexcept {
  return DINT(static_cast<std::int32_t>(detail::unwrapped_t<W>::upper(dim.value)));
}

/**
 * A VAR_OUTPUT of a METHOD or FUNCTION. It starts each call at its declared initial value,
 * the body assigns it like any variable, and a call that names it (`"x"_ >> y`, ST's
 * `x => y`) receives its value in `y` when the call's variables end.
 *
 * A copy or move of a bound output delivers into the output it was made from, so a method
 * that hands its variables on (`SUPER::M(in)`) still delivers to its own caller.
 */
template <class T>
class output : public detail::condition_conversion<output<T>, T>, public detail::widening_conversion<output<T>, T> {
 public:
  using value_type = T;
  using iecoop_value_wrapper = void;

  constexpr output()
    requires(!std::is_enum_v<T>)
  = default;
  /// A variable of an enumeration declared without an initial value: its start, or refused
  /// here where iecoop does not know it, so that the report names the declaration's own line.
  constexpr output() noexcept
    requires(std::is_enum_v<T>)
      : value_(detail::enum_start_or_zero<T>()) {
    detail::refuse_unknown_enum_start<T>();
  }
  /// The declared initial value: `output<INT> x{5};` (ST: `x : INT := 5;`).
  constexpr explicit output(const T& initial) : value_(initial) {}
  constexpr output(const output& other) : value_(other.value_) {
    if (other.target_ != nullptr) bind_result(const_cast<output&>(other).value_);
  }
  constexpr output(output&& other) noexcept : output(static_cast<const output&>(other)) {}
  constexpr output& operator=(const output& other) {
    value_ = other.value_;
    return *this;
  }
  constexpr output& operator=(output&& other) noexcept { return *this = static_cast<const output&>(other); }
  constexpr ~output() {
    if (target_ != nullptr) deliver_(target_, value_);
  }

  constexpr output& operator=(const T& value) {
    detail::copy_value(value_, value);
    return *this;
  }
  /// From another variable wrapper whose value converts implicitly.
  template <class V>
    requires detail::converts_through_wrapper<T, V>
  constexpr output& operator=(const V& other) {
    detail::assign_value(value_, detail::value_of(other));
    return *this;
  }
  /// A value of a type that ST converts only explicitly: rejected, naming the conversion.
  template <class V>
    requires detail::rejected_value<T, V>
  constexpr void operator=(const V&) {
    detail::reject_value<T, V>();
  }
  constexpr operator const T&() const noexcept { return value_; }  // implicit: reads as the variable
  [[nodiscard]] constexpr const T& get() const noexcept { return value_; }
  constexpr T& ref() noexcept { return value_; }
  constexpr decltype(auto) operator->() const noexcept { return detail::arrow_of(value_); }
  constexpr decltype(auto) operator->() noexcept { return detail::arrow_of(value_); }

  /// Makes the call copy this output to `target` when it ends (ST's `=>`), converting as
  /// IEC allows; the target may be a variable, a block's var<> or an in-out.
  template <class Target>
  constexpr void bind_result(Target& target) noexcept {
    target_ = &target;
    deliver_ = [](void* t, const T& v) { detail::deliver_output(*static_cast<Target*>(t), v); };
  }

 private:
  T value_ = detail::initial_value<T>();
  void* target_ = nullptr;
  void (*deliver_)(void*, const T&) = nullptr;
};

/**
 * A VAR of a METHOD or FUNCTION, declared with its inputs and outputs in the variables struct
 * (`temp<INT> x;` for `VAR x : INT; END_VAR`): it starts every call at its declared initial
 * value, the body reads and writes it as `in.x` like the method's other variables, and no
 * caller passes it. So every plain name of a method's ST is `in.` + the name when the method
 * declares it (ST: the method's variables shadow the block's), and the block's is `this->x`
 * (THIS^.x) — with no C++ local shadowing a member.
 */
template <class T>
class temp : public detail::assignable_variable<temp<T>, T> {
  using base = detail::assignable_variable<temp<T>, T>;

 public:
  constexpr temp()
    requires(!std::is_enum_v<T>)
  = default;
  /// A variable of an enumeration declared without an initial value: its start, or refused
  /// here where iecoop does not know it, so that the report names the declaration's own line.
  constexpr temp() noexcept
    requires(std::is_enum_v<T>)
      : base(detail::enum_start_or_zero<T>()) {
    detail::refuse_unknown_enum_start<T>();
  }
  /// The declared initial value: `temp<INT> x{5};` (ST: `x : INT := 5;`).
  constexpr explicit temp(const T& initial) : base(initial) {}
  constexpr temp(const temp&) = default;
  constexpr temp& operator=(const temp&) = default;
  using base::operator=;
};

namespace detail {
template <class T>
struct is_output : std::false_type {};
template <class T>
struct is_output<output<T>> : std::true_type {};
template <class T>
struct is_temp : std::false_type {};
template <class T>
struct is_temp<temp<T>> : std::true_type {};
}  // namespace detail

}  // namespace iecoop

#include <iecoop/detail/pop_macros.hpp>
