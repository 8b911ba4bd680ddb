// SPDX-License-Identifier: MIT
// iecoop/types/pointer.hpp — POINTER TO, ADR, SIZEOF and XSIZEOF as CODESYS has them.
//
// `p : POINTER TO INT;` is `POINTER_TO<INT> p;`, `p := ADR(x);` is `p = ADR(x);`, `p^` is `*p`
// and `p^.member` is `p->member`. Dereferencing a null pointer is a fault
// (fault_kind::null_pointer) — the place of CODESYS's implicit CheckPointer — after which the
// access goes to a stand-in value instead of address 0. Pointer arithmetic counts bytes, as in
// CODESYS (`p := p + SIZEOF(p^)` steps to the next element), not elements as in C++; `p[i]`
// indexes elements, as CODESYS's index access on pointers does.
//
// __NEW and __DELETE are not offered: the core has no heap after start-up. Give objects static
// or instance storage (an ARRAY of them, with a free list where they come and go).
#pragma once

#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <type_traits>

#include <iecoop/config.hpp>
#include <iecoop/detail/meta.hpp>
#include <iecoop/fault.hpp>
#include <iecoop/types/detail/initial_value.hpp>
#include <iecoop/types/elementary.hpp>

#include <iecoop/detail/push_macros.hpp>

namespace iecoop {

namespace detail {

/// The variable a variable wrapper (var<>, retain<>, ...) holds, or the variable itself.
template <class X>
constexpr auto& referenced_variable(X& x) noexcept {
  if constexpr (requires { x.ref(); }) {
    return x.ref();
  } else {
    return x;
  }
}

}  // namespace detail

/**
 * ST's `POINTER TO T`: 0 until assigned (`ADR(x)`), dereferenced as `*p` (ST: `p^`).
 *
 *     POINTER_TO<INT> pValue;            // pValue : POINTER TO INT;
 *     pValue = ADR(iCount);              // pValue := ADR(iCount);
 *     *pValue = *pValue + 1;             // pValue^ := pValue^ + 1;
 *     if (pValue != nullptr) { ... }     // IF pValue <> 0 THEN
 *
 * Trivially copyable and as large as an address, like CODESYS's pointers.
 */
template <class T>
class POINTER_TO {
 public:
  using element_type = T;

  constexpr POINTER_TO() noexcept = default;
  constexpr POINTER_TO(std::nullptr_t) noexcept {}  // implicit: p := 0
  /// From a C++ pointer (C APIs, `this`).
  constexpr explicit POINTER_TO(T* address) noexcept : address_(address) {}
  /// A pointer to a derived block is a pointer to its base block (EXTENDS), and any pointer
  /// converts to one of the same type with const added.
  template <class U>
    requires(!std::is_same_v<U, T> && std::is_convertible_v<U*, T*>)
  constexpr POINTER_TO(POINTER_TO<U> other) noexcept : address_(other.get()) {}  // implicit: as in ST

  /// ST's `p^`. A null pointer is a fault; the access then goes to a stand-in variable.
  [[nodiscard]] constexpr T& operator*() const {
    if (address_ == nullptr) [[unlikely]]
      return null_target();
    return *address_;
  }
  /// ST's `p^.member` and `p^.Method()`.
  [[nodiscard]] constexpr T* operator->() const { return &**this; }
  /// ST's `p[i]`: the i-th element from the address (i * SIZEOF(T) bytes on).
  template <class I>
  [[nodiscard]] constexpr T& operator[](const I& index) const {
    if (address_ == nullptr) [[unlikely]]
      return null_target();
    return address_[static_cast<std::ptrdiff_t>(integer_value(index))];
  }

  /// The address as a C++ pointer (nullptr for 0).
  [[nodiscard]] constexpr T* get() const noexcept { return address_; }

  friend constexpr bool operator==(POINTER_TO a, POINTER_TO b) noexcept { return a.address_ == b.address_; }
  friend constexpr bool operator==(POINTER_TO a, std::nullptr_t) noexcept { return a.address_ == nullptr; }

  /// ST's `p + n`: n BYTES on, as in CODESYS (not n elements, as in C++).
  template <class I>
  friend POINTER_TO operator+(POINTER_TO p, const I& bytes) noexcept {
    return p.moved(static_cast<std::ptrdiff_t>(integer_value(bytes)));
  }
  /// ST's `p - n`: n bytes back.
  template <class I>
  friend POINTER_TO operator-(POINTER_TO p, const I& bytes) noexcept {
    return p.moved(-static_cast<std::ptrdiff_t>(integer_value(bytes)));
  }
  template <class I>
  POINTER_TO& operator+=(const I& bytes) noexcept {
    return *this = *this + bytes;
  }
  template <class I>
  POINTER_TO& operator-=(const I& bytes) noexcept {
    return *this = *this - bytes;
  }

 private:
  template <class I>
  static constexpr auto integer_value(const I& i) noexcept {
    static_assert(detail::cpp_integer<I> || detail::is_integer<I>::value || detail::is_intermediate<I>::value,
                  "iecoop: a pointer moves by an integer number of bytes (and p[i] takes an integer index)");
    if constexpr (detail::cpp_integer<I>) {
      return i;
    } else {
      return i.value();
    }
  }
  POINTER_TO moved(std::ptrdiff_t bytes) const noexcept {
    // Through the integer value of the address: CODESYS adds bytes to an address, which may
    // leave T's alignment; dereferencing such a pointer is the caller's business, as there.
    return POINTER_TO(
        reinterpret_cast<T*>(reinterpret_cast<std::uintptr_t>(address_) + static_cast<std::uintptr_t>(bytes)));
  }
  static T& null_target() {
    fault(fault_kind::null_pointer, "POINTER dereferenced while it is 0; a stand-in variable is used");
    using V = std::remove_const_t<T>;
    if constexpr (std::is_default_constructible_v<V> && std::is_copy_assignable_v<V>) {
      static V stand_in = detail::stand_in_value<V>();
      detail::refresh_stand_in(stand_in);
      return stand_in;
    } else {
      std::abort();  // no stand-in can be made for this type (an abstract block)
    }
  }

  T* address_ = nullptr;
};

/// ST's `ADR(x)`: the address of a variable (of a block, of a wrapper's variable), typed.
template <class X>
[[nodiscard]] constexpr auto ADR(X& variable) noexcept {
  auto& target = detail::referenced_variable(variable);
  return POINTER_TO<std::remove_reference_t<decltype(target)>>(&target);
}
template <class X>
  requires(!std::is_lvalue_reference_v<X>)
auto ADR(X&&) noexcept {
  static_assert(detail::dependent_false<X>,
                "iecoop: ADR takes a variable; a temporary (a value, a function's result) has no address after the "
                "statement");
  return POINTER_TO<std::remove_cvref_t<X>>();
}

namespace detail {

template <std::size_t N>
constexpr auto sized_unsigned() noexcept {
  if constexpr (N < 256) {
    return USINT(static_cast<std::uint8_t>(N));
  } else if constexpr (N < 65536) {
    return UINT(static_cast<std::uint16_t>(N));
  } else if constexpr (N <= 0xFFFF'FFFFU) {
    return UDINT(static_cast<std::uint32_t>(N));
  } else {
    return ULINT(static_cast<std::uint64_t>(N));
  }
}

}  // namespace detail

/// ST's `SIZEOF(x)`: x's size in bytes, as the smallest unsigned type that holds it (USINT
/// below 256, then UINT, UDINT, ULINT), as CODESYS does. iecoop's types are as large as
/// CODESYS's, so the numbers agree for IEC types, STRINGs, ARRAYs and STRUCTs of them.
template <class X>
[[nodiscard]] constexpr auto SIZEOF(const X&) noexcept {
  return detail::sized_unsigned<sizeof(
      std::remove_cvref_t<decltype(detail::referenced_variable(std::declval<std::remove_cvref_t<X>&>()))>)>();
}
/// ST's `SIZEOF(T)` of a type: SIZEOF<ST_Recipe>().
template <class T>
[[nodiscard]] constexpr auto SIZEOF() noexcept {
  return detail::sized_unsigned<sizeof(T)>();
}
/// ST's `XSIZEOF(x)`: the size as the platform's unsigned register type (UDINT on 32-bit
/// targets, ULINT on 64-bit ones), as CODESYS's __UXINT.
template <class X>
[[nodiscard]] constexpr auto XSIZEOF(const X& x) noexcept {
  using uxint = std::conditional_t<sizeof(void*) >= 8, ULINT, UDINT>;
  return uxint(SIZEOF(x).value());
}

}  // namespace iecoop

#include <iecoop/detail/pop_macros.hpp>
