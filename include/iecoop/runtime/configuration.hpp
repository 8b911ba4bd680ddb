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
  if constexpr (!(e::is_task || e::is_globals || e::is_image || e::is_capacity)) {
    static_assert(!program_type<E>,
                  "iecoop: a PROGRAM is assigned to no task; name it in a task (task<PRG>{\"Main\", "
                  "cyclic{\"T#10ms\"_iec}, 1}) — "
                  "a program that only other POUs call is declared as an ordinary variable");
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

  /// The tasks' settings, in configuration order.
  static std::array<task_settings, task_count> task_settings_of(const Entries&... entries) noexcept {
    static_assert(entries_valid);
    std::array<task_settings, task_count> settings{};
    std::size_t i = 0;
    (
        [&] {
          if constexpr (entry<Entries>::is_task) settings[i++] = entries.settings();
        }(),
        ...);
    return settings;
  }

  /// The checks of the located variables of every owned instance (all in the image).
  static constexpr void check_located_variables() { located_check<image, owned_list>::run(); }
};

}  // namespace detail

}  // namespace iecoop

#include <iecoop/detail/pop_macros.hpp>
