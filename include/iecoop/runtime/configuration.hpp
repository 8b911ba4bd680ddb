// SPDX-License-Identifier: MIT
// iecoop/runtime/configuration.hpp — what an application is made of, as CODESYS's
// application tree lists it: tasks (task<...>{...}, <iecoop/runtime/task.hpp>), global
// variable lists (globals<...>{}), the process image (use_image<...>{}) and the retain memory
// (retain_capacity<N>{}); and what follows from the list, computed while compiling: the
// instances the application owns, its tasks in order, its image and retain size. A program
// in no task, a second image, or a located variable in another image does not compile.
#pragma once

#include <array>
#include <cstddef>
#include <type_traits>

#include <iecoop/config.hpp>
#include <iecoop/detail/meta.hpp>
#include <iecoop/io/located.hpp>
#include <iecoop/io/process_image.hpp>
#include <iecoop/pou/call_interface.hpp>
#include <iecoop/runtime/task.hpp>

#include <iecoop/detail/push_macros.hpp>

namespace iecoop {

/// Global variable lists (VAR_GLOBAL, with RETAIN and PERSISTENT members) the application owns:
/// it constructs them at start, resets them with the programs and keeps their retained values.
/// Reach one with application::get<GVL>(), or, from any POU, with GVL::instance() when the
/// list derives from global_variables<GVL> (<iecoop/pou/global_variables.hpp>).
template <class... Lists>
struct globals {};

/// The process image the application's tasks latch (default_process_image if not given).
template <class Image>
struct use_image {};

/// The bytes the application keeps for RETAIN and PERSISTENT values over a reset or a stop
/// (its retain memory); 1024 if not given.
template <std::size_t Bytes>
struct retain_capacity {};

namespace detail {

// What an application entry is.
template <class E>
struct entry {
  static constexpr bool is_task = false, is_globals = false, is_image = false, is_capacity = false;
};
template <class... P>
struct entry<task<P...>> {
  static constexpr bool is_task = true, is_globals = false, is_image = false, is_capacity = false;
};
template <class... G>
struct entry<globals<G...>> {
  static constexpr bool is_task = false, is_globals = true, is_image = false, is_capacity = false;
};
template <class I>
struct entry<use_image<I>> {
  static constexpr bool is_task = false, is_globals = false, is_image = true, is_capacity = false;
};
template <std::size_t N>
struct entry<retain_capacity<N>> {
  static constexpr bool is_task = false, is_globals = false, is_image = false, is_capacity = true;
};

template <class E>
constexpr void check_entry() {
  using e = entry<E>;
  if constexpr (global_list_type<E> || program_type<E>) {
    // reported by the application's constructor, naming the type (first_outside<...>)
  } else if constexpr (!(e::is_task || e::is_globals || e::is_image || e::is_capacity)) {
    static_assert(
        program_type<E>,
        "iecoop: an application is made of task<...>{...}, globals<...>{}, use_image<...>{} and retain_capacity<N>{}");
  }
}

// The instances an application owns: its global variable lists first, then every program of
// its tasks, each once, in order of first mention.
template <class List, class E>
struct add_globals {
  using type = List;
};
template <class List, class... G>
struct add_globals<List, globals<G...>> : push_all<List, G...> {};
template <class List, class E>
struct add_programs {
  using type = List;
};
template <class List, class... P>
struct add_programs<List, task<P...>> : push_all<List, P...> {};

template <class List, class E>
struct add_task {
  using type = List;
};
template <class... Ts, class... P>
struct add_task<type_list<Ts...>, task<P...>> {
  using type = type_list<Ts..., task<P...>>;
};

template <class Default, class... Es>
struct image_of {
  using type = Default;
};
template <class Default, class I, class... Es>
struct image_of<Default, use_image<I>, Es...> {
  using type = I;
};
template <class Default, class E, class... Es>
struct image_of<Default, E, Es...> : image_of<Default, Es...> {};

template <std::size_t Default, class... Es>
struct retain_capacity_of : std::integral_constant<std::size_t, Default> {};
template <std::size_t Default, std::size_t N, class... Es>
struct retain_capacity_of<Default, retain_capacity<N>, Es...> : std::integral_constant<std::size_t, N> {};
template <std::size_t Default, class E, class... Es>
struct retain_capacity_of<Default, E, Es...> : retain_capacity_of<Default, Es...> {};

template <class Image, class... Objects>
struct located_check;
template <class Image, class... Objects>
struct located_check<Image, type_list<Objects...>> {
  template <auto... Members>
  static constexpr bool in_image(pins<Members...>) noexcept {
    return (std::is_same_v<typename located_type_of<Members>::image_type, Image> && ...);
  }
  static constexpr void run() {
    check_located<Objects...>();
    using list = all_located_t<Objects...>;
    if constexpr (all_located(list{})) {
      static_assert(
          in_image(list{}),
          "iecoop: a located variable of the application's programs or global variable lists lies in another "
          "process image than the application's; give it the application's image: located<T, \"%...\", Image>, "
          "with Image as in use_image<Image>{}");
    }
  }
};

// The first entry that is a Kind (a global variable list given as it is, not in globals<...>{};
// a program given as it is, in no task), void if none: the application's constructor names it
// in its refusal.
template <template <class> class Kind, class... Es>
struct first_given_as_is {
  using type = void;
};
template <template <class> class Kind, class E, class... Es>
struct first_given_as_is<Kind, E, Es...>
    : std::conditional_t<Kind<E>::value, std::type_identity<E>, first_given_as_is<Kind, Es...>> {};
template <class E>
struct entry_is_global_list : std::bool_constant<global_list_type<E>> {};
template <class E>
struct entry_is_program : std::bool_constant<program_type<E>> {};

/// A program's VAR_EXTERNAL that names a list the application does not list (in a refusal).
template <class Program, class List>
struct VAR_EXTERNAL_not_in_globals {};
/// A program's VAR_EXTERNAL that is not globals<...> (in a refusal).
template <class Program, class External>
struct VAR_EXTERNAL_not_globals {};

// A program's VAR_EXTERNAL (`using VAR_EXTERNAL = globals<GVL_A, GVL_B>;`, the global variable
// lists it uses, as ST's VAR_EXTERNAL names the global variables): `type` is the first fault
// in it against the lists `Listed` (a type_list), void if none.
template <class Listed, class Program, class External>
struct external_fault {
  using type = VAR_EXTERNAL_not_globals<Program, External>;
};
template <class Listed, class Program>
struct external_fault<Listed, Program, void> {
  using type = void;
};
template <class Program, class... Listed, class... Lists>
struct external_fault<type_list<Listed...>, Program, globals<Lists...>> {
  template <class... Ls>
  struct first {
    using type = void;
  };
  template <class L, class... Ls>
  struct first<L, Ls...> : std::conditional_t<occurs_in<L, Listed...>, first<Ls...>,
                                              std::type_identity<VAR_EXTERNAL_not_in_globals<Program, L>>> {};
  using type = typename first<Lists...>::type;
};
template <class Fault, bool NotInGlobals>
struct external_kind {
  using type = void;
};
template <class P, class L>
struct external_kind<VAR_EXTERNAL_not_in_globals<P, L>, true> {
  using type = VAR_EXTERNAL_not_in_globals<P, L>;
};
template <class P, class X>
struct external_kind<VAR_EXTERNAL_not_globals<P, X>, false> {
  using type = VAR_EXTERNAL_not_globals<P, X>;
};
template <class P>
struct external_of {
  using type = void;
};
template <class P>
  requires requires { typename P::VAR_EXTERNAL; }
struct external_of<P> {
  using type = typename P::VAR_EXTERNAL;
};
template <class Listed, class... Owned>
struct first_external_fault {
  using type = void;
};
template <class Listed, class O, class... Owned>
struct first_external_fault<Listed, O, Owned...>
    : std::conditional_t<std::is_void_v<typename external_fault<Listed, O, typename external_of<O>::type>::type>,
                         first_external_fault<Listed, Owned...>,
                         external_fault<Listed, O, typename external_of<O>::type>> {};

// first_external_fault over a type_list of the owned instances (a class template, not a lambda
// in decltype: clang 14 crashes on that in a class template's member alias).
template <class Listed, class OwnedList>
struct first_external_fault_in;
template <class Listed, class... Owned>
struct first_external_fault_in<Listed, type_list<Owned...>> : first_external_fault<Listed, Owned...> {};

/// An application's configuration, `Entries...` as given to application{...}.
template <class... Entries>
struct configuration {
  static constexpr bool entries_valid = ((check_entry<Entries>(), true) && ...);
  static_assert((0 + ... + (entry<Entries>::is_image ? 1 : 0)) <= 1,
                "iecoop: an application has one process image; give use_image<...>{} once");
  static_assert((0 + ... + (entry<Entries>::is_capacity ? 1 : 0)) <= 1,
                "iecoop: an application has one retain memory; give retain_capacity<N>{} once");

  /// The global variable lists, first in order of mention.
  using globals_list = typename fold_entries<add_globals, type_list<>, Entries...>::type;
  /// The instances the application owns: the lists, then every program of its tasks, each once.
  using owned_list = typename fold_entries<add_programs, globals_list, Entries...>::type;
  /// The tasks, in configuration order.
  using task_list = typename fold_entries<add_task, type_list<>, Entries...>::type;
  using image = typename image_of<default_process_image, Entries...>::type;
  static constexpr std::size_t retain_bytes = retain_capacity_of<1024, Entries...>::value;
  static constexpr std::size_t task_count = (0 + ... + (entry<Entries>::is_task ? 1 : 0));
  static_assert(task_count > 0, "iecoop: an application needs at least one task; add task<PRG>{...}");

  /// Whether the application owns an instance of T.
  template <class T>
  static constexpr bool owns =
      [] { return []<class... Ts>(type_list<Ts...>) { return occurs_in<T, Ts...>; }(owned_list{}); }();

  /// Whether T is one of the application's global variable lists.
  template <class T>
  static constexpr bool lists =
      [] { return []<class... Ts>(type_list<Ts...>) { return occurs_in<T, Ts...>; }(globals_list{}); }();

  /// The tasks' settings, in configuration order: where each is (in `entries`, which the
  /// scheduler copies them from once).
  static std::array<const task_settings*, task_count> task_settings_of(const Entries&... entries) noexcept {
    static_assert(entries_valid);
    std::array<const task_settings*, task_count> settings{};
    std::size_t i = 0;
    (
        [&] {
          if constexpr (entry<Entries>::is_task) settings[i++] = &entries.settings();
        }(),
        ...);
    return settings;
  }

  /// The checks of the located variables of every owned instance (all in the image).
  static constexpr void check_located_variables() { located_check<image, owned_list>::run(); }

  /// The first global variable list given outside globals<...>{}, void if none.
  using list_outside_globals = typename first_given_as_is<entry_is_global_list, Entries...>::type;
  /// The first program given as it is, in no task, void if none.
  using program_outside_tasks = typename first_given_as_is<entry_is_program, Entries...>::type;
  /// The first fault in a program's VAR_EXTERNAL, void if none: VAR_EXTERNAL_not_globals<P, X>
  /// or VAR_EXTERNAL_not_in_globals<P, GVL>.
  using external_fault = typename first_external_fault_in<globals_list, owned_list>::type;
  /// That fault if it is a list the application does not list, void otherwise.
  using external_not_in_globals = typename external_kind<external_fault, true>::type;
  /// That fault if the VAR_EXTERNAL is not globals<...>, void otherwise.
  using external_not_globals = typename external_kind<external_fault, false>::type;
};

}  // namespace detail

}  // namespace iecoop

#include <iecoop/detail/pop_macros.hpp>
