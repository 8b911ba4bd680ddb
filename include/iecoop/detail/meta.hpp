// SPDX-License-Identifier: MIT
// iecoop/detail/meta.hpp — the generic type-level helpers every layer uses: type lists and
// what is asked of them (does a type occur, are all distinct, concatenate, append unique).
// IWYU pragma: private, include <iecoop/iecoop.hpp>
#pragma once

#include <type_traits>

namespace iecoop::detail {

/// false, but only once T is known: for static_assert in templates that must not be used.
template <class...>
inline constexpr bool dependent_false = false;

/// What a refusal names: `static_assert(none<T>, "...")` fails for any T but void, and the
/// compiler shows T (the offending type, found by the template) beside the message.
template <class T>
inline constexpr bool none = std::is_void_v<T>;

template <class... T>
struct type_list {};

/// Whether T is one of Ts.
template <class T, class... Ts>
inline constexpr bool occurs_in = (std::is_same_v<T, Ts> || ...);

/// Whether no type occurs twice in Ts.
template <class... Ts>
struct all_distinct : std::true_type {};
template <class T, class... Ts>
struct all_distinct<T, Ts...> : std::bool_constant<!occurs_in<T, Ts...> && all_distinct<Ts...>::value> {};

/// concat<type_list<A...>, type_list<B...>, ...>::type is type_list<A..., B..., ...>.
template <class... L>
struct concat {
  using type = type_list<>;
};
template <class... A>
struct concat<type_list<A...>> {
  using type = type_list<A...>;
};
template <class... A, class... B, class... Rest>
struct concat<type_list<A...>, type_list<B...>, Rest...> {
  using type = typename concat<type_list<A..., B...>, Rest...>::type;
};

/// push_unique<type_list<Ts...>, T>::type: the list with T appended, unless T is in it.
template <class List, class T>
struct push_unique;
template <class... Ts, class T>
struct push_unique<type_list<Ts...>, T> {
  using type = std::conditional_t<occurs_in<T, Ts...>, type_list<Ts...>, type_list<Ts..., T>>;
};

/// push_all<List, Ts...>::type: each of Ts appended to List unless it is there already.
template <class List, class... Ts>
struct push_all {
  using type = List;
};
template <class List, class T, class... Ts>
struct push_all<List, T, Ts...> : push_all<typename push_unique<List, T>::type, Ts...> {};

/// fold_entries<Step, List, Es...>::type: List passed through Step<List, E>::type for each E.
template <template <class, class> class Step, class List, class... Es>
struct fold_entries {
  using type = List;
};
template <template <class, class> class Step, class List, class E, class... Es>
struct fold_entries<Step, List, E, Es...> : fold_entries<Step, typename Step<List, E>::type, Es...> {};

/// The base block of a block made with extends<> (its iecoop_base_block), or void.
template <class B>
struct base_of {
  using type = void;
};
template <class B>
  requires requires { typename B::iecoop_base_block; }
struct base_of<B> {
  using type = typename B::iecoop_base_block;
};

/// The attributes a block's own declaration lists (pou/attributes.hpp; not those of the
/// blocks it extends), or void.
template <class B>
struct own_attributes {
  using type = void;
};
template <class B>
  requires requires { typename B::iecoop_attributes; }
struct own_attributes<B> {
  using type = typename B::iecoop_attributes;
};
template <class B>
using own_attributes_t = typename own_attributes<B>::type;

/// B (or a block it extends) is declared no_assign ({attribute 'no_assign'}).
template <class B>
constexpr bool refuses_assignment() noexcept {
  if constexpr (std::is_void_v<B> || !std::is_class_v<B>) {
    return false;
  } else {
    if constexpr (!std::is_void_v<own_attributes_t<B>>) {
      if constexpr (own_attributes_t<B>::iecoop_no_assign) return true;
    }
    return refuses_assignment<typename base_of<B>::type>();
  }
}

}  // namespace iecoop::detail
