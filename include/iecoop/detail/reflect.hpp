// SPDX-License-Identifier: MIT
// iecoop/detail/reflect.hpp — compile-time reflection of the little iecoop needs: the fields of an
// aggregate (a METHOD's or FUNCTION's variables, an IEC STRUCT), with their names, and the
// name of a member a pointer-to-member designates.
//
// Names are read from the compiler's spelling of a template argument (__PRETTY_FUNCTION__),
// the technique C++ has for this before C++26 reflection. Supported: GCC >= 12, Clang >= 14.
//
//     struct DoIt_vars { DWORD iInput_1; DWORD iInput_2; STRING<12> sInput_3; };
//     static_assert(field_count<DoIt_vars> == 3);
//     static_assert(field_name<DoIt_vars, 2> == "sInput_3");
//     static_assert(member_name<&DoIt_vars::iInput_2> == "iInput_2");
// IWYU pragma: private, include <iecoop/iecoop.hpp>
#pragma once

#include <array>
#include <cstddef>
#include <string_view>
#include <tuple>
#include <type_traits>
#include <utility>

#include <iecoop/config.hpp>
#include <iecoop/detail/any_field.hpp>
#include <iecoop/detail/field_binding.hpp>

#include <iecoop/detail/push_macros.hpp>

namespace iecoop {

namespace detail {

template <class T, std::size_t... I>
constexpr bool initializable_with(std::index_sequence<I...>) noexcept {
  return requires { T{(void(I), any_field{})...}; };
}

template <class T, std::size_t N = 0>
constexpr std::size_t count_fields() noexcept {
  if constexpr (N > max_reflected_fields || !initializable_with<T>(std::make_index_sequence<N + 1>{})) {
    return N;
  } else {
    return count_fields<T, N + 1>();
  }
}

/// Cuts the entity's name out of a __PRETTY_FUNCTION__ text of the form
/// "... [with auto P = <expression ending in the name>; ...]" (GCC) or
/// "... [P = <expression ending in the name>]" (Clang).
constexpr std::string_view name_in_signature(std::string_view signature) noexcept {
  std::size_t end = signature.find("; ", signature.find(" = "));
  if (end == std::string_view::npos) end = signature.rfind(']');
  std::string_view expression = signature.substr(0, end);
  while (!expression.empty() && (expression.back() == ')' || expression.back() == '}' || expression.back() == ' ')) {
    expression.remove_suffix(1);
  }
  const std::size_t separator = expression.find_last_of(":.>& ");
  return expression.substr(separator + 1);
}

template <auto Entity>
constexpr std::string_view signature_of() noexcept {
#if defined(__GNUC__) || defined(__clang__)
  return __PRETTY_FUNCTION__;
#else
#error "iecoop: reflection needs GCC or Clang (__PRETTY_FUNCTION__)"
#endif
}

// A pointer to a field of an object that is declared but never defined, wrapped in a class
// so that Clang 14 accepts it as a template argument (it rejects bare pointers to
// subobjects). Only its spelling in signature_of<> is ever used.
template <class T>
struct reflected_object {
  const T value;
};
#if defined(__clang__)
#pragma clang diagnostic push
#pragma clang diagnostic ignored "-Wundefined-var-template"
#pragma clang diagnostic ignored "-Wundefined-internal"
#endif
template <class T>
extern const reflected_object<T> declared_only;

template <class F>
struct field_pointer {
  const F* pointer;
};

template <class T, std::size_t I, std::size_t N>
consteval auto field_pointer_of() noexcept {
  return visit_fields<N>(declared_only<T>.value, [](const auto&... fields) {
    const auto pointers = std::make_tuple(&fields...);
    using field_type = std::remove_cvref_t<decltype(*std::get<I>(pointers))>;
    return field_pointer<field_type>{std::get<I>(pointers)};
  });
}
#if defined(__clang__)
#pragma clang diagnostic pop
#endif

}  // namespace detail

/// The number of fields of the aggregate T (at most 32).
template <class T>
inline constexpr std::size_t field_count = detail::count_fields<T>();

/// A type iecoop can reflect: an aggregate with at most 32 fields, none of them a C array.
template <class T>
concept Reflectable = std::is_aggregate_v<T> && !std::is_array_v<T> && field_count<T> <= detail::max_reflected_fields;

/// The name of the I-th field (from 0) of the aggregate T.
template <Reflectable T, std::size_t I>
inline constexpr std::string_view field_name =
    detail::name_in_signature(detail::signature_of<detail::field_pointer_of<T, I, field_count<T>>()>());

/// The type of the I-th field of the aggregate T.
template <Reflectable T, std::size_t I>
using field_type = std::remove_cvref_t<decltype(*detail::field_pointer_of<T, I, field_count<T>>().pointer)>;

/// Calls f(field_0, ..., field_N-1) with references to the fields of an aggregate.
template <class T, class F>
  requires Reflectable<std::remove_const_t<T>>
constexpr decltype(auto) apply_fields(T& object, F&& f) {
  return detail::visit_fields<field_count<std::remove_const_t<T>>>(object, std::forward<F>(f));
}

/// The I-th field of an aggregate.
template <std::size_t I, class T>
  requires Reflectable<std::remove_const_t<T>>
constexpr auto& get_field(T& object) {
  return apply_fields(object, [](auto&... fields) -> auto& { return std::get<I>(std::tie(fields...)); });
}

/// The index of the field called `name` in T, or field_count<T> if there is none.
template <Reflectable T>
constexpr std::size_t field_index(std::string_view name) noexcept {
  constexpr auto names = []<std::size_t... I>(std::index_sequence<I...>) {
    return std::array<std::string_view, sizeof...(I)>{field_name<T, I>...};
  }(std::make_index_sequence<field_count<T>>{});
  for (std::size_t i = 0; i < names.size(); ++i) {
    if (names[i] == name) return i;
  }
  return names.size();
}

/// The name of the data member a pointer-to-member designates: member_name<&TON::PT> == "PT".
template <auto Member>
  requires std::is_member_object_pointer_v<decltype(Member)>
inline constexpr std::string_view member_name = detail::name_in_signature(detail::signature_of<Member>());

}  // namespace iecoop

#include <iecoop/detail/pop_macros.hpp>
