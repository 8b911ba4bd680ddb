// SPDX-License-Identifier: MIT
// iecoop/sfc/elements.hpp — the elements of a chart as IEC textual SFC spells them: steps with
// their action associations, transitions, qualifiers, priorities, time limits, and the scan
// order. They are types: a chart's structure is fixed at compile time and checked there
// (iecoop/sfc/chart.hpp).
//
//     // INITIAL_STEP INIT: A_INIT(N); END_STEP
//     sfc::INITIAL_STEP<&P::INIT, sfc::N<&P::A_INIT>>,
//     // TRANSITION FROM INIT TO FILL := START; END_TRANSITION
//     sfc::TRANSITION<sfc::FROM<&P::INIT>, sfc::TO<&P::FILL>, &P::START>,
//     // STEP S1: A_L(L, T#30ms); V_D(D, T#30ms); END_STEP
//     sfc::STEP<&P::S1, sfc::L<&P::A_L, "T#30ms">, sfc::D<&P::V_D, "T#30ms">>,
#pragma once

#include <cstddef>
#include <cstdint>
#include <string_view>
#include <type_traits>

#include <iecoop/config.hpp>
#include <iecoop/detail/fixed_string.hpp>
#include <iecoop/detail/meta.hpp>
#include <iecoop/sfc/step.hpp>
#include <iecoop/types/elementary.hpp>
#include <iecoop/types/literals.hpp>
#include <iecoop/types/time.hpp>

#include <iecoop/detail/push_macros.hpp>

namespace iecoop::sfc {

// --- Scan orders ------------------------------------------------------------------------

/// CODESYS's and TwinCAT's order (the default): in each cycle the actions first (with a final
/// scan of each action whose Q fell), then the transitions; the steps a transition leads to
/// are active from the next cycle on.
struct codesys {
  static constexpr std::string_view name = "codesys";
  static constexpr bool actions_first = true;
};
/// The order of IEC textual SFC as MatIEC (Beremiz, OpenPLC) compiles it: the transitions
/// first, then the actions of the steps now active, in the same scan; no final scan. iecoop
/// follows IEC where that compiler does not (docs/sfc.md, "Two scan orders").
struct matiec {
  static constexpr std::string_view name = "matiec";
  static constexpr bool actions_first = false;
};
/// A scan order: sfc::codesys or sfc::matiec.
template <class T>
concept ScanOrder = std::is_same_v<T, codesys> || std::is_same_v<T, matiec>;

/// After the scan order (or first): the engine that runs the chart (docs/sfc.md, "How a chart is
/// run"). Both compute the same, scan for scan. The compiled engine is code written for each set
/// of steps the chart can have active together (at most 64 sets): faster, and larger. The
/// general engine keeps the active steps and the actions' Q as bit sets: smaller. Without
/// either, a chart gets the compiled engine where it can, except in a build optimised for size
/// (-Os, as firmware is built), which gets the general one.
struct general_engine {};
/// See general_engine: the compiled engine also under -Os (where the chart has at most 64 sets
/// of active steps; else the general one).
struct compiled_engine {};

// --- Action associations ----------------------------------------------------------------

/// IEC's action qualifiers.
enum class qualifier : std::uint8_t { N, S, R, P, P1, P0, L, D, SD, DS, SL };

namespace detail {

/// The TIME a duration literal of an SFC element stands for ("T#30ms"), checked as "..."_iec
/// checks it.
template <fixed_string Text>
consteval TIME duration_literal() noexcept {
  using iecoop::literals::operator""_iec;
  constexpr auto value = operator""_iec<Text>();
  static_assert(std::is_same_v<std::remove_cvref_t<decltype(value)>, TIME>,
                "iecoop: an SFC duration is a TIME literal; write it as in ST, e.g. \"T#30ms\"");
  return value;
}

/// What kind of chart element a type is.
enum class element_kind : std::uint8_t { step, transition, association, step_action, time_limit, final_mark };

/// What a CODESYS step action is.
enum class step_action_kind : std::uint8_t { entry, active, exit };

}  // namespace detail

/// An association of a step with an action under a qualifier: the action is a member
/// function of the POU (an ACTION) or a BOOL member (a variable as action).
template <qualifier Q, auto Action, TIME::rep DurationMs = 0>
struct association {
  static constexpr detail::element_kind iecoop_sfc_element = detail::element_kind::association;
  static constexpr qualifier kind = Q;
  static constexpr auto action = Action;
  static constexpr TIME duration = TIME::from_ticks(DurationMs);
};

/// `A(N)`: the action is active while the step is.
template <auto Action>
using N = association<qualifier::N, Action>;
/// `A(S)`: set (stored) when the step is active; active until an R resets it.
template <auto Action>
using S = association<qualifier::S, Action>;
/// `A(R)`: resets a stored action (overriding: while the R step is active, the action is not).
template <auto Action>
using R = association<qualifier::R, Action>;
/// `A(P)`: a pulse, one scan, when the step is activated (in the codesys order the body then
/// runs twice: the pulse and the final scan, as CODESYS documents).
template <auto Action>
using P = association<qualifier::P, Action>;
/// `A(P1)`: a pulse when the step is activated (IEC edition 3): the body runs once, without a
/// final scan.
template <auto Action>
using P1 = association<qualifier::P1, Action>;
/// `A(P0)`: a pulse when the step is deactivated (IEC edition 3): the body runs once, without a
/// final scan.
template <auto Action>
using P0 = association<qualifier::P0, Action>;
/// `A(L, T#30ms)`: active while the step is, for at most the duration.
template <auto Action, fixed_string Duration>
using L = association<qualifier::L, Action, detail::duration_literal<Duration>().count()>;
/// `A(D, T#30ms)`: active while the step is, from the duration after its activation on.
template <auto Action, fixed_string Duration>
using D = association<qualifier::D, Action, detail::duration_literal<Duration>().count()>;
/// `A(SD, T#30ms)`: stored, then delayed: active from the duration after the step's activation
/// on, even if the step was left meanwhile, until an R.
template <auto Action, fixed_string Duration>
using SD = association<qualifier::SD, Action, detail::duration_literal<Duration>().count()>;
/// `A(DS, T#30ms)`: delayed, then stored: stored only if the step is still active the duration
/// after its activation; then active until an R.
template <auto Action, fixed_string Duration>
using DS = association<qualifier::DS, Action, detail::duration_literal<Duration>().count()>;
/// `A(SL, T#30ms)`: stored and limited: active for the duration from the step's activation,
/// unless an R cuts it short.
template <auto Action, fixed_string Duration>
using SL = association<qualifier::SL, Action, detail::duration_literal<Duration>().count()>;

// --- CODESYS step actions and step properties -------------------------------------------

template <detail::step_action_kind K, auto Action>
struct step_action {
  static constexpr detail::element_kind iecoop_sfc_element = detail::element_kind::step_action;
  static constexpr detail::step_action_kind kind = K;
  static constexpr auto action = Action;
};
/// CODESYS's entry action: runs once, in the step's first active cycle.
template <auto Action>
using on_entry = step_action<detail::step_action_kind::entry, Action>;
/// CODESYS's step action ("active"): runs in every cycle the step is active.
template <auto Action>
using while_active = step_action<detail::step_action_kind::active, Action>;
/// CODESYS's exit action: runs once, in the cycle after the step was left (codesys order) or in
/// the scan that leaves it (matiec order).
template <auto Action>
using on_exit = step_action<detail::step_action_kind::exit, Action>;

template <bool Maximum, TIME::rep Ms>
struct time_limit {
  static constexpr detail::element_kind iecoop_sfc_element = detail::element_kind::time_limit;
  static constexpr bool maximum = Maximum;
  static constexpr TIME limit = TIME::from_ticks(Ms);
};
/// The step's minimum time (CODESYS step property): no transition leaves it before its T reaches it.
template <fixed_string Duration>
using min_time = time_limit<false, detail::duration_literal<Duration>().count()>;
/// The step's maximum time (CODESYS step property): a step active longer sets SFCError.
template <fixed_string Duration>
using max_time = time_limit<true, detail::duration_literal<Duration>().count()>;

/// Marks a final step: one that no transition leaves, by design (the chart's check accepts it).
struct final_step {
  static constexpr detail::element_kind iecoop_sfc_element = detail::element_kind::final_mark;
};

// --- Steps --------------------------------------------------------------------------------

namespace detail {
template <class T>
concept step_item =
    requires {
      { T::iecoop_sfc_element } -> std::convertible_to<element_kind>;
    } && (T::iecoop_sfc_element == element_kind::association || T::iecoop_sfc_element == element_kind::step_action ||
          T::iecoop_sfc_element == element_kind::time_limit || T::iecoop_sfc_element == element_kind::final_mark);

template <class M>
struct step_member : std::false_type {};
template <class C>
struct step_member<sfc::step C::*> : std::true_type {};

template <bool Initial, auto Step, class... Items>
struct step_element {
  static_assert(step_member<decltype(Step)>::value,
                "iecoop: STEP<> and INITIAL_STEP<> name a step member of the POU; declare `sfc::step FILL;` in it and "
                "write STEP<&P::FILL, ...>");
  static_assert((step_item<Items> && ...),
                "iecoop: a STEP<> holds action associations (N<&P::A>, S<>, L<&P::A, \"T#1s\">, ...), step actions "
                "(on_entry<>, while_active<>, on_exit<>), min_time<>/max_time<> and final_step; move other elements "
                "out of the step");
  static constexpr element_kind iecoop_sfc_element = element_kind::step;
  static constexpr bool initial = Initial;
  static constexpr auto member = Step;
  using items = iecoop::detail::type_list<Items...>;
};
}  // namespace detail

/// `STEP FILL: A_FILL(N); END_STEP` is `sfc::STEP<&P::FILL, sfc::N<&P::A_FILL>>`.
template <auto Step, class... Items>
using STEP = detail::step_element<false, Step, Items...>;
/// `INITIAL_STEP INIT: ... END_STEP` is `sfc::INITIAL_STEP<&P::INIT, ...>`: one per chart.
template <auto Step, class... Items>
using INITIAL_STEP = detail::step_element<true, Step, Items...>;

// --- Transitions --------------------------------------------------------------------------

/// The source steps of a transition: `FROM (P2, Q2)` is `sfc::FROM<&P::P2, &P::Q2>`.
template <auto... Steps>
struct FROM {
  static constexpr std::size_t size = sizeof...(Steps);
};
/// The target steps of a transition: `TO (P1, Q1)` is `sfc::TO<&P::P1, &P::Q1>`.
template <auto... Steps>
struct TO {
  static constexpr std::size_t size = sizeof...(Steps);
};
/// `TRANSITION (PRIORITY := 2) ...`: among alternatives, the lowest number is tested first.
template <int Priority>
struct PRIORITY {
  static constexpr int value = Priority;
};

namespace detail {
template <class T>
struct is_from : std::false_type {};
template <auto... S>
struct is_from<FROM<S...>> : std::true_type {};
template <class T>
struct is_to : std::false_type {};
template <auto... S>
struct is_to<TO<S...>> : std::true_type {};
template <class T>
struct is_priority : std::false_type {};
template <int N>
struct is_priority<PRIORITY<N>> : std::true_type {};

/// The priority the options give (PRIORITY<n>), else `none`.
inline constexpr int no_priority = 2147483647;
template <class... Options>
consteval int priority_of() noexcept {
  int result = no_priority;
  ((result = Options::value), ...);
  return result;
}
}  // namespace detail

namespace detail {

/// What a transition's condition yields, where its type tells it while the POU is still
/// incomplete (inside its class): `type` is that result, `known` FALSE for a generic callable
/// (`[](auto& p) {...}`), which the chart checks where it runs (chart(*this)).
template <class C>
struct condition_result {
  static constexpr bool known = false;
  static constexpr bool callable = false;
  using type = void;
};
template <class M, class P>
struct condition_result<M P::*> {
  static constexpr bool known = true;
  static constexpr bool callable = true;
  using type = M&;
};
template <class R, class P>
struct condition_result<R (P::*)()> {
  static constexpr bool known = true;
  static constexpr bool callable = true;
  using type = R;
};
template <class R, class P>
struct condition_result<R (P::*)() const> {
  static constexpr bool known = true;
  static constexpr bool callable = true;
  using type = R;
};
template <class R, class P>
struct condition_result<R (P::*)() noexcept> {
  static constexpr bool known = true;
  static constexpr bool callable = true;
  using type = R;
};
template <class R, class P>
struct condition_result<R (P::*)() const noexcept> {
  static constexpr bool known = true;
  static constexpr bool callable = true;
  using type = R;
};
template <class R, class P>
struct condition_result<R (*)(P&)> {
  static constexpr bool known = true;
  static constexpr bool callable = true;
  using type = R;
};
template <class R, class P>
struct condition_result<R (*)(P&) noexcept> : condition_result<R (*)(P&)> {};
template <class C>
  requires std::is_class_v<C>
struct condition_result<C> {
  // A callable with one operator() (a lambda taking the POU by its type): its result is known;
  // a generic one (`auto& p`) is checked by the chart.
  template <class F>
  struct call {
    static constexpr bool known = false;
    using type = void;
  };
  template <class F>
    requires requires { &F::operator(); }
  struct call<F> {
    template <class M>
    struct result_of;
    template <class R, class F2, class... A>
    struct result_of<R (F2::*)(A...) const> {
      using type = R;
    };
    template <class R, class F2, class... A>
    struct result_of<R (F2::*)(A...) const noexcept> {
      using type = R;
    };
    template <class R, class F2, class... A>
    struct result_of<R (F2::*)(A...)> {
      using type = R;
    };
    template <class R, class F2, class... A>
    struct result_of<R (F2::*)(A...) noexcept> {
      using type = R;
    };
    static constexpr bool known = true;
    using type = typename result_of<decltype(&F::operator())>::type;
  };
  static constexpr bool known = call<C>::known;
  static constexpr bool callable = true;
  using type = typename call<C>::type;
};

/// Whether a condition's result is a BOOL: bool, BOOL, a BOOL variable (a member, read_only<>,
/// a step's X) or a bit — anything that converts to BOOL, which no number does (INT, REAL,
/// int or double: compare them, `p.nCount != 0`).
template <class R>
inline constexpr bool bool_result = std::is_convertible_v<R, BOOL>;

/// Condition, checked where the TRANSITION is declared, with the transition's arguments.
template <class From, class To, auto Condition, class... Options>
consteval auto checked_transition() {
  static_assert(detail::is_from<From>::value,
                "iecoop: a TRANSITION's first argument is its source steps; write sfc::FROM<&P::S1> or "
                "sfc::FROM<&P::P2, &P::Q2>");
  static_assert(detail::is_to<To>::value,
                "iecoop: a TRANSITION's second argument is its target steps; write sfc::TO<&P::S2> or "
                "sfc::TO<&P::P1, &P::Q1>");
  static_assert((detail::is_priority<Options>::value && ...) && sizeof...(Options) <= 1,
                "iecoop: a TRANSITION's only option is its priority; write sfc::PRIORITY<1> after the condition");
  using C = decltype(Condition);
  using result = condition_result<C>;
  constexpr bool bool_condition =
      std::is_same_v<C, bool> || (result::callable && (!result::known || bool_result<typename result::type>));
  static_assert(bool_condition,
                "iecoop: a TRANSITION's condition is a BOOL; this one (the third template argument) yields a number "
                "or another type — compare it: [](auto& p) { return p.nCount != 0; } (ST: nCount <> 0), or name a "
                "BOOL member (&P::bDone) or a method returning BOOL");
  if constexpr (bool_condition) {
    return Condition;
  } else {
    return true;  // a valid condition in its place: one error, not a second one in the chart
  }
}

template <class From, class To, auto Condition, class... Options>
struct transition {
  static_assert(From::size > 0, "iecoop: a TRANSITION needs a source step; write sfc::FROM<&P::S1>");
  static_assert(To::size > 0, "iecoop: a TRANSITION needs a target step; write sfc::TO<&P::S2>");
  static constexpr detail::element_kind iecoop_sfc_element = detail::element_kind::transition;
  using from = From;
  using to = To;
  static constexpr auto condition = Condition;
  static constexpr int priority = detail::priority_of<Options...>();
};

}  // namespace detail

/**
 * `TRANSITION FROM FILL TO PULSE := <condition>; END_TRANSITION`.
 *
 * The condition is a BOOL member (`&P::START`), a member function returning BOOL — a named
 * transition object, virtual if a derived POU may override it (`&P::T_Filled`) —, a callable
 * taking the POU (`[](auto& p) { return p.FILL.T >= 50ms; }`; a duration in it as a chrono literal:
 * Clang 14 with UBSan crashes on an "..."_iec literal there), or `true`. The option
 * `sfc::PRIORITY<n>` is ST's `(PRIORITY := n)`.
 *
 * A condition that is no BOOL (an INT member, a method or lambda returning a number) does not
 * compile: ST's `nCount <> 0` is `[](auto& p) { return p.nCount != 0; }`. It is refused here,
 * where the transition is declared; a generic callable (`auto& p`), whose result only the
 * complete POU tells, is refused where the chart runs (`chart(*this)`).
 */
template <class From, class To, auto Condition, class... Options>
using TRANSITION =
    detail::transition<From, To, detail::checked_transition<From, To, Condition, Options...>(), Options...>;

}  // namespace iecoop::sfc

#include <iecoop/detail/pop_macros.hpp>
