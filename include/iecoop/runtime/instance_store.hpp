// SPDX-License-Identifier: MIT
// iecoop/runtime/instance_store.hpp — raw storage for an application's instances (its
// programs and global variable lists), constructed and destroyed as a whole: construction
// is when FB_Init runs, destruction when FB_Exit runs, and a reset destroys and reconstructs
// each instance in place as its exact type (docs/design.md, "The application owns its programs").
// IWYU pragma: private, include <iecoop/runtime/application.hpp>
#pragma once

#include <array>
#include <cstddef>
#include <new>
#include <tuple>
#include <utility>

#include <iecoop/config.hpp>
#include <iecoop/detail/meta.hpp>
#include <iecoop/runtime/retain_image.hpp>

#include <iecoop/detail/push_macros.hpp>

namespace iecoop::detail {

template <class T>
struct instance_slot {
  alignas(T) std::byte bytes[sizeof(T)];
};

/// Raw storage for one instance of each of `Ts...` (a type_list).
template <class List>
class instance_store;
template <class... Ts>
class instance_store<type_list<Ts...>> {
 public:
  template <class T>
  [[nodiscard]] T& get() noexcept {
    return *std::launder(reinterpret_cast<T*>(std::get<instance_slot<T>>(slots_).bytes));
  }
  /// Constructs every instance, in order.
  void construct_all() { (::new (static_cast<void*>(std::get<instance_slot<Ts>>(slots_).bytes)) Ts(), ...); }
  /// Destroys every instance, in reverse order.
  void destroy_all() { destroy_reversed(std::make_index_sequence<sizeof...(Ts)>{}); }

  /// Where each instance lives, for saving and restoring its retained variables.
  [[nodiscard]] std::array<retained_object, sizeof...(Ts)> objects() const noexcept {
    return {retained_object{std::get<instance_slot<Ts>>(slots_).bytes, sizeof(Ts)}...};
  }

 private:
  template <std::size_t... I>
  void destroy_reversed(std::index_sequence<I...>) {
    using types = std::tuple<Ts...>;
    (destroy(get<std::tuple_element_t<sizeof...(Ts) - 1 - I, types>>()), ...);
  }

  template <class T>
  static void destroy(T& instance) noexcept {
    instance.~T();
  }

  std::tuple<instance_slot<Ts>...> slots_;
};

}  // namespace iecoop::detail

#include <iecoop/detail/pop_macros.hpp>
