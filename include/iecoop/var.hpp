// SPDX-License-Identifier: MIT
// iecoop/var.hpp — variable sections whose rules C++ members do not have by themselves:
//   local<T, Owner>  VAR of a block: readable from outside (as CODESYS allows), written only
//                    by the block that declares it — write `var<T>` inside a block
//   in_out<T>        VAR_IN_OUT: a reference bound at the call; using it unbound is a fault
//   output<T>        VAR_OUTPUT of a METHOD or FUNCTION: `"x"_ >> y` copies it out after the call
//
// VAR_INPUT and the VAR_OUTPUT of blocks and programs are plain members.
#pragma once

#include <cstdlib>
#include <type_traits>
#include <utility>

#include <iecoop/config.hpp>
#include <iecoop/detail/lifecycle_state.hpp>
#include <iecoop/detail/scalar_access.hpp>
#include <iecoop/detail/value_operators.hpp>
#include <iecoop/fault.hpp>

#include <iecoop/detail/push_macros.hpp>

namespace iecoop {

template <class T, class Owner>
class local;
template <class T>
class in_out;

namespace detail {

/// iecoop's own write access to a block's local: the target of `"Q"_ >> local` in a call.
struct local_access {
  template <class T, class Owner>
  static constexpr T& ref(local<T, Owner>& variable) noexcept {
    return variable.value_;
  }
};

template <class T>
struct is_local : std::false_type {};
template <class T, class O>
struct is_local<local<T, O>> : std::true_type {};
template <class T>
struct is_in_out : std::false_type {};
template <class T>
struct is_in_out<in_out<T>> : std::true_type {};

/// The variable `=>` writes into: a local's or in-out's value, or the variable itself.
template <class Target>
constexpr auto& output_target(Target& target) {
  if constexpr (is_local<Target>::value) {
    return local_access::ref(target);
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

/**
 * A block's local variable (VAR ... END_VAR): `var<INT> count{5};` inside the block.
 *
 * Everyone can read it (`fb.count`, `fb.count + 1`), as CODESYS lets outside code read a
 * block's locals; only the declaring block `Owner` can assign it (`count = count + 1;`
 * inside Owner's body and methods), as CODESYS forbids writing them from outside — and a
 * call's `"Q"_ >> count` delivers into it. A block derived from Owner reads it too; if it
 * must also write it, declare the variable in a C++ `protected:` section instead (IEC 3rd
 * edition's VAR PROTECTED).
 */
template <class T, class Owner>
class local {
 public:
  using value_type = T;
  using iecoop_value_wrapper = void;  // in expressions, its value (detail/value_operators.hpp)

  constexpr local() = default;
  /// The declaration's initial value: `var<INT> count{5};`
  constexpr explicit local(const T& initial) : value_(initial) {}
  constexpr local(const local&) = default;

  constexpr operator const T&() const noexcept { return value_; }  // NOLINT: reads as the variable
  [[nodiscard]] constexpr const T& get() const noexcept { return value_; }
  constexpr const T* operator->() const noexcept { return &value_; }
  /// `IF bFlag THEN` (the value's own test, which the implicit conversion cannot reach).
  explicit constexpr operator bool() const
    requires std::is_constructible_v<bool, const T&>
  {
    return static_cast<bool>(value_);
  }

 private:
  friend Owner;
  friend struct detail::local_access;

  constexpr local& operator=(const local&) = default;  // Owner's own copies (online change)
  // Values are copied as scalars (detail/scalar_access.hpp), so that the optimiser sees
  // plain loads and stores.
  constexpr local& operator=(const T& value) {
    detail::copy_value(value_, value);
    return *this;
  }
  // Non-template operands, so that constants convert as in any assignment (`count += 1`).
  constexpr local& operator+=(const T& v) {
    detail::assign_value(value_, value_ + v);
    return *this;
  }
  constexpr local& operator-=(const T& v) {
    detail::assign_value(value_, value_ - v);
    return *this;
  }
  constexpr local& operator*=(const T& v) {
    detail::assign_value(value_, value_ * v);
    return *this;
  }
  constexpr local& operator/=(const T& v) {
    detail::assign_value(value_, value_ / v);
    return *this;
  }
  constexpr local& operator++() {
    ++value_;
    return *this;
  }
  constexpr local& operator--() {
    --value_;
    return *this;
  }
  /// Write access for the owner, for members of structured locals: `pos.ref().x = 1;`
  constexpr T& ref() noexcept { return value_; }

  T value_{};
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
class in_out {
 public:
  using value_type = std::remove_const_t<T>;
  using iecoop_value_wrapper = void;

  constexpr in_out() noexcept = default;
  constexpr explicit in_out(T& variable) noexcept : target_(&variable) {}
  constexpr in_out(const in_out&) noexcept = default;

  /// Binds to `variable` (ST: `x := variable` in the call; REF= for references).
  constexpr void bind(T& variable) noexcept { target_ = &variable; }
  /// TRUE once bound (ST: __ISVALIDREF).
  [[nodiscard]] constexpr bool bound() const noexcept { return target_ != nullptr; }

  [[nodiscard]] constexpr T& get() const {
    if (target_ == nullptr) return unbound();
    return *target_;
  }
  constexpr operator T&() const { return get(); }  // NOLINT: reads as the variable
  explicit constexpr operator bool() const
    requires std::is_constructible_v<bool, const value_type&>
  {
    return static_cast<bool>(get());
  }
  constexpr T* operator->() const { return &get(); }

  /// Writes through to the bound variable (a non-template operand, so that constants
  /// convert as in any assignment).
  constexpr const in_out& operator=(const value_type& value) const
    requires(!std::is_const_v<T>)
  {
    detail::copy_value(get(), value);
    return *this;
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
      static value_type scratch = value_type();
      scratch = value_type();
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
 * A VAR_OUTPUT of a METHOD or FUNCTION. It starts each call at its declared initial value,
 * the body assigns it like any variable, and a call that names it (`"x"_ >> y`, ST's
 * `x => y`) receives its value in `y` when the call's variables end.
 *
 * A copy or move of a bound output delivers into the output it was made from, so a method
 * that hands its variables on (`SUPER::M(in)`) still delivers to its own caller.
 */
template <class T>
class output {
 public:
  using value_type = T;
  using iecoop_value_wrapper = void;

  constexpr output() = default;
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
  constexpr operator const T&() const noexcept { return value_; }  // NOLINT: reads as the variable
  [[nodiscard]] constexpr const T& get() const noexcept { return value_; }
  constexpr T& ref() noexcept { return value_; }
  explicit constexpr operator bool() const
    requires std::is_constructible_v<bool, const T&>
  {
    return static_cast<bool>(value_);
  }

  /// Makes the call copy this output to `target` when it ends (ST's `=>`), converting as
  /// IEC allows; the target may be a variable, a block's var<> or an in-out.
  template <class Target>
  constexpr void bind_result(Target& target) noexcept {
    target_ = &target;
    deliver_ = [](void* t, const T& v) { detail::deliver_output(*static_cast<Target*>(t), v); };
  }

 private:
  T value_{};
  void* target_ = nullptr;
  void (*deliver_)(void*, const T&) = nullptr;
};

namespace detail {
template <class T>
struct is_output : std::false_type {};
template <class T>
struct is_output<output<T>> : std::true_type {};
}  // namespace detail

}  // namespace iecoop

#include <iecoop/detail/pop_macros.hpp>
