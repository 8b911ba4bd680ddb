// SPDX-License-Identifier: MIT
// iecoop/var.hpp — variable sections whose rules C++ members do not have by themselves:
//   local<T, Owner>  VAR of a block: readable from outside (as CODESYS allows), written only
//                    by the block that declares it — write `var<T>` inside a block
//   in_out<T>        VAR_IN_OUT: a reference bound at the call; using it unbound is a fault
//   output<T>        VAR_OUTPUT of a METHOD or FUNCTION: `"x"_ >> y` copies it out after the call
//
// VAR_INPUT and the VAR_OUTPUT of blocks and programs are plain members.
#pragma once

#include <type_traits>
#include <utility>

#include <iecoop/config.hpp>
#include <iecoop/fault.hpp>

#include <iecoop/detail/push_macros.hpp>

namespace iecoop {

namespace detail {

/// Comparisons of a wrapper (local, in_out, output) that see through to its value, also where
/// the value's own operators are templates that would not look through the wrapper's
/// implicit conversion (STRING's `== 'text'`).
template <class Wrapper, class T>
struct compares_as_value {
  template <class U>
    requires(!std::is_same_v<U, Wrapper>)
  friend constexpr auto operator==(const Wrapper& a, const U& b) -> decltype(std::declval<const T&>() == b) {
    return a.get() == b;
  }
  template <class U>
    requires(!std::is_same_v<U, Wrapper>)
  friend constexpr auto operator<=>(const Wrapper& a, const U& b) -> decltype(std::declval<const T&>() <=> b) {
    return a.get() <=> b;
  }
  friend constexpr auto operator==(const Wrapper& a, const Wrapper& b)
      -> decltype(std::declval<const T&>() == std::declval<const T&>()) {
    return a.get() == b.get();
  }
};

}  // namespace detail

/**
 * A block's local variable (VAR ... END_VAR): `var<INT> count{0};` inside the block.
 *
 * Everyone can read it (`fb.count`, `fb.count + 1`), as CODESYS lets outside code read a
 * block's locals; only the declaring block `Owner` can assign it (`count = count + 1;`
 * inside Owner's body and methods), as CODESYS forbids writing them from outside. A block
 * derived from Owner reads it too; if it must also write it, declare the variable in a C++
 * `protected:` section instead (IEC 3rd edition's VAR PROTECTED).
 */
template <class T, class Owner>
class local : public detail::compares_as_value<local<T, Owner>, T> {
 public:
  using value_type = T;

  constexpr local() = default;
  /// The declaration's initial value: `var<INT> count{5};`
  constexpr explicit local(const T& initial) : value_(initial) {}

  constexpr operator const T&() const noexcept { return value_; }  // NOLINT: reads as the variable
  [[nodiscard]] constexpr const T& get() const noexcept { return value_; }
  constexpr const T* operator->() const noexcept { return &value_; }

 private:
  friend Owner;

  constexpr local& operator=(const T& value) {
    value_ = value;
    return *this;
  }
  // Non-template operands, so that constants convert as in any assignment (`count += 1`).
  constexpr local& operator+=(const T& v) {
    value_ = value_ + v;
    return *this;
  }
  constexpr local& operator-=(const T& v) {
    value_ = value_ - v;
    return *this;
  }
  constexpr local& operator*=(const T& v) {
    value_ = value_ * v;
    return *this;
  }
  constexpr local& operator/=(const T& v) {
    value_ = value_ / v;
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
  /// Write access for the owner, for members of structured locals: `count.ref().x = 1;`
  constexpr T& ref() noexcept { return value_; }

  T value_{};
};

/**
 * VAR_IN_OUT: a reference to the caller's variable, bound at the call (`"x"_ = var`, or
 * `fb.x.bind(var)`), read and written through like the variable itself.
 *
 * Reading or writing it while unbound reports fault_kind::unbound_in_out (and then works on
 * a scratch variable, so nothing undefined happens); calling a block whose VAR_IN_OUT is
 * unbound reports the same fault and skips the body. `in_out<const T>` is VAR_IN_OUT
 * CONSTANT.
 */
template <class T>
class in_out : public detail::compares_as_value<in_out<T>, std::remove_const_t<T>> {
 public:
  using value_type = std::remove_const_t<T>;

  constexpr in_out() noexcept = default;
  constexpr explicit in_out(T& variable) noexcept : target_(&variable) {}

  /// Binds to `variable` (ST: `x := variable` in the call; REF= for references).
  constexpr void bind(T& variable) noexcept { target_ = &variable; }
  /// TRUE once bound (ST: __ISVALIDREF).
  [[nodiscard]] constexpr bool bound() const noexcept { return target_ != nullptr; }

  [[nodiscard]] constexpr T& get() const {
    if (target_ == nullptr) return unbound();
    return *target_;
  }
  constexpr operator T&() const { return get(); }  // NOLINT: reads as the variable
  constexpr T* operator->() const { return &get(); }

  /// Writes through to the bound variable (a non-template operand, so that constants
  /// convert as in any assignment).
  constexpr const in_out& operator=(const value_type& value) const
    requires(!std::is_const_v<T>)
  {
    get() = value;
    return *this;
  }
  constexpr in_out& operator=(const in_out&) = default;  // copies the binding (online change)
  constexpr in_out(const in_out&) = default;

 private:
  static T& unbound() {
    fault(fault_kind::unbound_in_out, "VAR_IN_OUT used before it was bound to a variable");
    static value_type scratch{};
    scratch = value_type{};
    return scratch;
  }

  T* target_ = nullptr;
};

/**
 * A VAR_OUTPUT of a METHOD or FUNCTION. It starts each call at its declared initial value,
 * the body assigns it like any variable, and a call that names it (`"x"_ >> y`, ST's
 * `x => y`) receives its value in `y` when the call returns.
 */
template <class T>
class output : public detail::compares_as_value<output<T>, T> {
 public:
  using value_type = T;

  constexpr output() = default;
  /// The declared initial value: `output<INT> x{5};` (ST: `x : INT := 5;`).
  constexpr explicit output(const T& initial) : value_(initial) {}
  output(const output& other) : detail::compares_as_value<output<T>, T>(), value_(other.value_) {}  // a copy is not bound
  output& operator=(const output& other) {
    value_ = other.value_;
    return *this;
  }
  /// Moving hands the binding over: the moved-to output delivers the value.
  constexpr output(output&& other) noexcept
      : detail::compares_as_value<output<T>, T>(), value_(std::move(other.value_)), target_(other.target_) {
    other.target_ = nullptr;
  }
  constexpr output& operator=(output&& other) noexcept {
    value_ = std::move(other.value_);
    target_ = other.target_;
    other.target_ = nullptr;
    return *this;
  }
  constexpr ~output() {
    if (target_ != nullptr) *target_ = value_;
  }

  constexpr output& operator=(const T& value) {
    value_ = value;
    return *this;
  }
  constexpr operator const T&() const noexcept { return value_; }  // NOLINT: reads as the variable
  [[nodiscard]] constexpr const T& get() const noexcept { return value_; }
  constexpr T& ref() noexcept { return value_; }

  /// Makes the call copy this output to `*target` when it ends (ST's `=>`).
  constexpr void bind_result(T* target) noexcept { target_ = target; }

 private:
  T value_{};
  T* target_ = nullptr;
};

namespace detail {
template <class T>
struct is_in_out : std::false_type {};
template <class T>
struct is_in_out<in_out<T>> : std::true_type {};
template <class T>
struct is_output : std::false_type {};
template <class T>
struct is_output<output<T>> : std::true_type {};
}  // namespace detail

}  // namespace iecoop

#include <iecoop/detail/pop_macros.hpp>
