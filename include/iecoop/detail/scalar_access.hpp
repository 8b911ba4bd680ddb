// SPDX-License-Identifier: MIT
// iecoop/detail/scalar_access.hpp — copying the value of an IEC elementary type (BOOL, the
// integers, REAL, TIME) as the one scalar it holds.
// IWYU pragma: private, include <iecoop/iecoop.hpp>
//
// Why not just `a = b`: each elementary type is a class around one scalar, and GCC 12
// compiles the copy of such an object between two variables in memory as an aggregate copy,
// which its loop optimiser cannot analyse — a loop containing one keeps every variable it
// touches in memory — and a store of a freshly made value through a pointer as an access
// its alias analysis gives up on. A load and a store of the member are two plain scalar
// accesses. bench/ shows the difference on the standard scan workload (docs/performance.md).
// iecoop's wrappers (var<>, in_out<>, output<>, retain<>, a call's `:=`) and the standard
// blocks copy through here; user code keeps writing `a = b`.
#pragma once

#include <type_traits>
#include <utility>

namespace iecoop::detail {

/// TRUE for the elementary types that befriend scalar_access and keep their value in
/// `value_` (each type's header specialises it).
template <class T>
struct is_scalar_wrapper : std::false_type {};

struct scalar_access {
  template <class T>
  static constexpr auto& ref(T& x) noexcept {
    return x.value_;
  }
  template <class T>
  static constexpr const auto& ref(const T& x) noexcept {
    return x.value_;
  }
};

/// `target = value;` for two variables of the same type.
template <class T>
constexpr void copy_value(T& target, const T& value) {
  if constexpr (is_scalar_wrapper<T>::value) {
    scalar_access::ref(target) = scalar_access::ref(value);
  } else {
    target = value;
  }
}

/// `target = value;` for a value of any type that converts implicitly to the target's.
template <class T, class V>
constexpr void assign_value(T& target, V&& value) {
  if constexpr (!is_scalar_wrapper<T>::value) {
    target = std::forward<V>(value);
  } else if constexpr (std::is_same_v<std::remove_cvref_t<V>, T>) {
    copy_value(target, value);
  } else if constexpr (std::is_convertible_v<V&&, T>) {
    const T converted = std::forward<V>(value);
    copy_value(target, converted);
  } else {
    target = std::forward<V>(value);  // T's own assignment, which says why it does not convert
  }
}

}  // namespace iecoop::detail
