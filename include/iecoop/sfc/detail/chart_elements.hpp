// SPDX-License-Identifier: MIT
// iecoop/sfc/detail/chart_elements.hpp — what a chart knows of its elements at compile time: the
// steps, transitions and actions in its list, the scan order, each TRANSITION's condition
// checked against the POU, the names of steps and actions, and the control of one IEC action
// (ACTION_CONTROL) the engine keeps per action.
// IWYU pragma: private, include <iecoop/sfc/chart.hpp>
#pragma once

#include <array>
#include <bit>
#include <cstddef>
#include <cstdint>
#include <string_view>
#include <type_traits>
#include <utility>

#include <iecoop/config.hpp>
#include <iecoop/detail/meta.hpp>
#include <iecoop/detail/reflect.hpp>
#include <iecoop/fault.hpp>
#include <iecoop/pou/variables.hpp>
#include <iecoop/sfc/elements.hpp>
#include <iecoop/sfc/step.hpp>
#include <iecoop/standard/cycle_clock.hpp>
#include <iecoop/types/detail/type_hash.hpp>
#include <iecoop/types/elementary.hpp>
#include <iecoop/types/string.hpp>
#include <iecoop/types/time.hpp>

#include <iecoop/detail/push_macros.hpp>

namespace iecoop::sfc {

namespace detail {

using iecoop::detail::type_list;

struct engine_access {
  static constexpr void name(step_name_view& view, std::string_view name) noexcept { view.name_ = name; }
  template <class T, class O>
  static constexpr T& ref(read_only<T, O>& variable) noexcept {
    return iecoop::detail::read_only_access::ref(variable);
  }
};

// --- The element lists ----------------------------------------------------------------------

template <element_kind K, class List>
struct only;
template <element_kind K>
struct only<K, type_list<>> {
  using type = type_list<>;
};
template <element_kind K, class E, class... Es>
struct only<K, type_list<E, Es...>> {
  using rest = typename only<K, type_list<Es...>>::type;
  using type =
      std::conditional_t<E::iecoop_sfc_element == K, typename iecoop::detail::concat<type_list<E>, rest>::type, rest>;
};

template <class T>
concept chart_element = requires {
  { T::iecoop_sfc_element } -> std::convertible_to<element_kind>;
} && (T::iecoop_sfc_element == element_kind::step || T::iecoop_sfc_element == element_kind::transition);

/// The engine a chart asks for: none (the default of the build), general or compiled.
enum class engine_choice : std::uint8_t { unset, general, compiled };
template <class E>
inline constexpr engine_choice engine_of = engine_choice::unset;
template <>
inline constexpr engine_choice engine_of<general_engine> = engine_choice::general;
template <>
inline constexpr engine_choice engine_of<compiled_engine> = engine_choice::compiled;
template <class E>
concept engine_tag = engine_of<E> != engine_choice::unset;

/// A chart's arguments after the POU: [scan order] [engine] elements.
template <class... Es>
struct split_order {
  using order = codesys;
  static constexpr engine_choice engine = engine_choice::unset;
  using elements = type_list<Es...>;
};
template <ScanOrder O, class... Es>
struct split_order<O, Es...> : split_order<Es...> {
  using order = O;
};
template <engine_tag E, class... Es>
struct split_order<E, Es...> : split_order<Es...> {
  static constexpr engine_choice engine = engine_of<E>;
};
template <ScanOrder O, engine_tag E, class... Es>
struct split_order<O, E, Es...> : split_order<Es...> {
  using order = O;
  static constexpr engine_choice engine = engine_of<E>;
};

template <std::size_t I, class List>
struct at;
template <std::size_t I, class E, class... Es>
struct at<I, type_list<E, Es...>> : at<I - 1, type_list<Es...>> {};
template <class E, class... Es>
struct at<0, type_list<E, Es...>> {
  using type = E;
};
template <std::size_t I, class List>
using at_t = typename at<I, List>::type;

template <class List>
struct length;
template <class... Es>
struct length<type_list<Es...>> : std::integral_constant<std::size_t, sizeof...(Es)> {};

/// One action, whatever the steps that name it.
template <auto A>
struct action_tag {
  static constexpr auto value = A;
};

template <class Steps>
struct actions_of;
template <class... Steps>
struct actions_of<type_list<Steps...>> {
  template <class Item, bool = Item::iecoop_sfc_element == element_kind::association>
  struct tag_of {
    using type = type_list<>;
  };
  template <class Item>
  struct tag_of<Item, true> {
    using type = type_list<action_tag<Item::action>>;
  };
  template <class Items>
  struct named;
  template <class... Items>
  struct named<type_list<Items...>> {
    using type = typename iecoop::detail::concat<type_list<>, typename tag_of<Items>::type...>::type;
  };
  template <class List>
  struct unique;
  template <class... Tags>
  struct unique<type_list<Tags...>> {
    using type = typename iecoop::detail::push_all<type_list<>, Tags...>::type;
  };
  using type =
      typename unique<typename iecoop::detail::concat<typename named<typename Steps::items>::type...>::type>::type;
};

// --- Calling the POU's members ------------------------------------------------------------

template <class M>
struct bool_member : std::false_type {};
template <class C>
struct bool_member<BOOL C::*> : std::true_type {};

/// Whether `Action` can be an action of POU: a member function without parameters, or a BOOL.
template <class POU, auto Action>
inline constexpr bool valid_action =
    bool_member<decltype(Action)>::value ||
    (std::is_member_function_pointer_v<decltype(Action)> && std::is_invocable_v<decltype(Action), POU&>);

/// Whether Condition is a BOOL condition on the complete POU: `true`, or a member, a method or
/// a callable whose result converts to BOOL (elements.hpp's bool_result: no number does).
template <class POU, auto Condition>
consteval bool valid_condition() noexcept {
  using C = decltype(Condition);
  if constexpr (std::is_same_v<C, bool>) {
    return true;
  } else if constexpr (std::is_invocable_v<C, POU&>) {
    return bool_result<std::invoke_result_t<C, POU&>>;
  } else {
    return false;
  }
}

/// The first of the transitions `Trs` (a type_list) whose condition is no BOOL on the complete
/// POU, void if none: a generic callable (`[](auto& p) {...}`), which the TRANSITION could
/// not check where it is declared.
template <class POU, class Trs>
struct first_non_bool_condition {
  using type = void;
};
template <class POU, class Tr, class... Trs>
struct first_non_bool_condition<POU, type_list<Tr, Trs...>>
    : std::conditional_t<valid_condition<POU, Tr::condition>(), first_non_bool_condition<POU, type_list<Trs...>>,
                         std::type_identity<Tr>> {};

template <auto Condition, class POU>
bool test(POU& pou) {
  using C = decltype(Condition);
  if constexpr (std::is_same_v<C, bool>) {
    return Condition;
  } else if constexpr (!valid_condition<POU, Condition>()) {
    return false;  // refused by the chart's operator() (no second error here)
  } else if constexpr (std::is_member_object_pointer_v<C>) {
    return static_cast<bool>(pou.*Condition);
  } else if constexpr (std::is_member_function_pointer_v<C>) {
    return static_cast<bool>((pou.*Condition)());
  } else {
    return static_cast<bool>(Condition(pou));
  }
}

// --- Structural checks (each names the offending step in its template argument) -------------

template <auto Step>
consteval void step_declared_twice() {
  static_assert(iecoop::detail::dependent_false<action_tag<Step>>,
                "iecoop: an SFC step is declared twice (the step in the template argument); declare each STEP once");
}
template <auto Step>
consteval void step_not_in_chart() {
  static_assert(iecoop::detail::dependent_false<action_tag<Step>>,
                "iecoop: a TRANSITION names a step that is no STEP of the chart (the step in the template argument); "
                "add sfc::STEP<&P::step> or fix the name");
}
template <auto Step>
consteval void step_never_left() {
  static_assert(iecoop::detail::dependent_false<action_tag<Step>>,
                "iecoop: no TRANSITION leaves the step in the template argument; add one FROM it, or mark it "
                "sfc::final_step");
}
template <auto Step>
consteval void step_unreachable() {
  static_assert(iecoop::detail::dependent_false<action_tag<Step>>,
                "iecoop: the step in the template argument cannot be reached from the initial step; add a TRANSITION "
                "TO it or remove it");
}
template <auto Action>
consteval void invalid_action() {
  static_assert(iecoop::detail::dependent_false<action_tag<Action>>,
                "iecoop: an SFC action is a member function of the POU without parameters (an ACTION) or a BOOL member "
                "(the action in the template argument is neither)");
}
inline constexpr std::size_t npos = static_cast<std::size_t>(-1);

/// The control of one IEC action (IEC 61131-3 ACTION_CONTROL, combined over its associations).
struct control {
  bool q = false;      // Q of the last scan
  bool pulse = false;  // ... driven only by P1 or P0 (CODESYS runs those once: no final scan)
  bool s = false;      // S stored
  bool sd = false;     // SD stored (its delay running since sd_et = 0)
  bool ds = false;     // DS stored
  bool sl = false;     // SL stored (its limit running since sl_et = 0)
  TIME sd_et{};
  TIME sl_et{};
  TIME sd_pt{};
  TIME sl_pt{};
};

}  // namespace detail

}  // namespace iecoop::sfc

#include <iecoop/detail/pop_macros.hpp>
