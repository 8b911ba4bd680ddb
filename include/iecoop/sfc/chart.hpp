// SPDX-License-Identifier: MIT
// iecoop/sfc/chart.hpp — a Sequential Function Chart: the body of a POU written in SFC.
//
//     struct P_SFC_LINEAR : program<P_SFC_LINEAR> {
//       BOOL START; INT C_FILL;
//       sfc::step INIT, FILL, PULSE;
//       void A_FILL() { C_FILL = C_FILL + 1; }                  // ACTION A_FILL
//       using P = P_SFC_LINEAR;
//       sfc::chart<P,
//         sfc::INITIAL_STEP<&P::INIT>,                          // INITIAL_STEP INIT: END_STEP
//         sfc::TRANSITION<sfc::FROM<&P::INIT>, sfc::TO<&P::FILL>, &P::START>,
//         sfc::STEP<&P::FILL, sfc::N<&P::A_FILL>>,              // STEP FILL: A_FILL(N); END_STEP
//         sfc::TRANSITION<sfc::FROM<&P::FILL>, sfc::TO<&P::PULSE>,
//                         [](auto& p) { return p.FILL.T >= 50ms; }>,   // chrono literals
//         sfc::STEP<&P::PULSE>,
//         sfc::TRANSITION<sfc::FROM<&P::PULSE>, sfc::TO<&P::INIT>, true>> chart;
//       void body() { chart(*this); }                           // one scan of the chart
//     };
//
// The structure is checked when the chart is compiled (one initial step, every step reached and
// left, transitions between the chart's steps, no step twice); the state is a few bytes per step
// and action inside the chart object, no heap. docs/sfc.md describes both scan orders.
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
#include <iecoop/sfc/detail/bit_set.hpp>
#include <iecoop/sfc/detail/chart_elements.hpp>
#include <iecoop/sfc/elements.hpp>
#include <iecoop/sfc/step.hpp>
#include <iecoop/standard/cycle_clock.hpp>
#include <iecoop/types/detail/type_hash.hpp>
#include <iecoop/types/elementary.hpp>
#include <iecoop/types/string.hpp>
#include <iecoop/types/time.hpp>

#include <iecoop/detail/push_macros.hpp>

namespace iecoop::sfc {

// The elements (steps, transitions, actions) as the chart sees them: sfc/detail/chart_elements.hpp.

namespace detail {

/// The SFC flags a POU writes (CODESYS's implicit variables), the chart's base: still the
/// chart's members (chart.SFCInit), and first in the chart's layout, where the test before each
/// scan reads them as one word (177.9 instructions a scan against 184.9 with five tests of
/// BOOLs, g++ 12; docs/performance.md, "SFC"), aligned: one load also where a load must be.
struct alignas(std::uint64_t) sfc_flags {
  BOOL SFCInit;               ///< while TRUE: reset to the initial step, no actions run
  BOOL SFCReset;              ///< while TRUE: reset to the initial step, then the scan goes on
  BOOL SFCPause;              ///< while TRUE: the chart holds (nothing runs, times stand still)
  BOOL SFCError;              ///< a step exceeded its max_time; a later timeout waits until reset
  BOOL SFCEnableLimit{TRUE};  ///< FALSE: maximum times are not checked
  BOOL SFCQuitError;          ///< while TRUE: the chart holds and SFCError is reset; on FALSE the
                              ///< active steps' times restart
  BOOL SFCTip;                ///< in tip mode, a rising edge fires the enabled transitions
  BOOL SFCTipMode;            ///< tip (jog) mode: transitions fire on SFCTip, not on their conditions

  /// Whether SFCInit, SFCReset, SFCPause, SFCQuitError, SFCTip or SFCTipMode is TRUE: the
  /// eight bytes as one word, the six flags' bytes masked (a BOOL is one byte, 0 or 1).
  [[nodiscard]] bool any_scan_flag() const noexcept { return (std::bit_cast<std::uint64_t>(*this) & scan_flags) != 0; }

 private:
  // The bytes of SFCInit, SFCReset, SFCPause, SFCQuitError, SFCTip and SFCTipMode (0, 1, 2, 5,
  // 6 and 7), written out; the pattern reads the same in both byte orders. With the mask
  // computed instead (a constant bit_cast of a sfc_flags), GCC 12.2 crashed — an internal
  // compiler error in tree_could_trap_p, compiling other code of the translation unit
  // (bench/scheduler_bench.cpp with -g -O3 and our warnings); the crash came and went with
  // unrelated changes (a -DFOO=1 on the command line avoided it), so it is GCC's, and this form
  // compiles every translation unit of the project (docs/performance.md, "SFC").
  static constexpr std::uint64_t scan_flags = 0x0101'0100'0001'0101U;
};
static_assert(sizeof(sfc_flags) == sizeof(std::uint64_t) && offsetof(sfc_flags, SFCInit) == 0 &&
                  offsetof(sfc_flags, SFCReset) == 1 && offsetof(sfc_flags, SFCPause) == 2 &&
                  offsetof(sfc_flags, SFCQuitError) == 5 && offsetof(sfc_flags, SFCTip) == 6 &&
                  offsetof(sfc_flags, SFCTipMode) == 7,
              "iecoop: the SFC flags are eight BOOLs of one byte each, in the order scan_flags masks");

}  // namespace detail

/**
 * A Sequential Function Chart over the POU `POU`, of the Elements (STEPs, TRANSITIONs), in the
 * scan order given first (sfc::codesys, the default, or sfc::matiec). Declare it as a member of
 * the POU after the steps and call it from the body: `void body() { chart(*this); }`.
 *
 * The SFC flags of CODESYS are its members: the POU writes SFCInit, SFCReset, SFCPause,
 * SFCEnableLimit (TRUE: as if not declared in CODESYS), SFCQuitError, SFCTip, SFCTipMode and
 * may reset SFCError; the chart writes SFCError, SFCErrorStep, SFCErrorPOU, SFCCurrentStep and
 * SFCTrans.
 */
template <class POU, class... Elements>
class chart : public detail::sfc_flags {
  using split = detail::split_order<Elements...>;
  using all = typename split::elements;

 public:
  /// The scan order.
  using order = typename split::order;

 private:
  static_assert([]<class... Es>(detail::type_list<Es...>) { return (detail::chart_element<Es> && ...); }(all{}),
                "iecoop: a chart holds STEP<>, INITIAL_STEP<> and TRANSITION<> elements, after an optional scan order "
                "(sfc::codesys or sfc::matiec) and an optional engine (sfc::general_engine or sfc::compiled_engine)");

  using steps = typename detail::only<detail::element_kind::step, all>::type;
  using transitions = typename detail::only<detail::element_kind::transition, all>::type;
  using actions = typename detail::actions_of<steps>::type;

  static constexpr std::size_t step_count = detail::length<steps>::value;
  static constexpr std::size_t transition_count = detail::length<transitions>::value;
  static constexpr std::size_t action_count = detail::length<actions>::value;

  static_assert(step_count > 0, "iecoop: an SFC chart needs steps; declare an sfc::INITIAL_STEP<> and its STEP<>s");

  template <std::size_t I>
  using step_at = detail::at_t<I, steps>;
  template <std::size_t I>
  using transition_at = detail::at_t<I, transitions>;
  template <std::size_t I>
  static constexpr auto action_at = detail::at_t<I, actions>::value;

  static constexpr std::size_t initial_count = []<class... S>(detail::type_list<S...>) {
    return (std::size_t{S::initial} + ...);
  }(steps{});
  static_assert(initial_count != 0,
                "iecoop: an SFC chart has exactly one INITIAL_STEP; declare its first step as sfc::INITIAL_STEP<>");
  static_assert(initial_count <= 1,
                "iecoop: an SFC chart has exactly one INITIAL_STEP; declare the others as sfc::STEP<>");

  using member = sfc::step POU::*;
  static constexpr std::array<member, step_count> members = []<class... S>(detail::type_list<S...>) {
    return std::array<member, step_count>{static_cast<member>(S::member)...};
  }(steps{});

  static constexpr std::size_t initial_index = [] {
    std::size_t i = 0;
    [&]<class... S>(detail::type_list<S...>) {
      std::size_t k = 0;
      ((S::initial ? (i = k, ++k) : ++k), ...);
    }(steps{});
    return i;
  }();

  static constexpr std::size_t index_of(member m) noexcept {
    for (std::size_t i = 0; i < step_count; ++i) {
      if (members[i] == m) return i;
    }
    return detail::npos;
  }

  // The step list, checked: no step twice.
  template <std::size_t I>
  static consteval bool check_step() {
    if constexpr (index_of(members[I]) != I) {
      detail::step_declared_twice<step_at<I>::member>();
      return false;
    }
    return true;
  }

  template <class Tr>
  struct ends {
    template <class List>
    struct indices;
    template <auto... S>
    struct indices<FROM<S...>> {
      static constexpr std::array<std::size_t, sizeof...(S)> value{index_of(static_cast<member>(S))...};
    };
    template <auto... S>
    struct indices<TO<S...>> {
      static constexpr std::array<std::size_t, sizeof...(S)> value{index_of(static_cast<member>(S))...};
    };
    static constexpr auto from = indices<typename Tr::from>::value;
    static constexpr auto to = indices<typename Tr::to>::value;
  };

  template <class Tr>
  static consteval bool check_transition() {
    check_ends(static_cast<typename Tr::from*>(nullptr));
    check_ends(static_cast<typename Tr::to*>(nullptr));
    return true;
  }
  template <template <auto...> class E, auto... S>
  static consteval void check_ends(E<S...>*) {
    (check_one_end<S>(), ...);
  }
  template <auto S>
  static consteval void check_one_end() {
    if constexpr (index_of(static_cast<member>(S)) == detail::npos) detail::step_not_in_chart<S>();
  }

  template <auto A>
  static consteval bool check_action() {
    if constexpr (!detail::valid_action<POU, A>) detail::invalid_action<A>();
    return true;
  }

  // Which steps a transition leaves and reaches; reachability from the initial step.
  static constexpr std::array<bool, step_count> left = [] {
    std::array<bool, step_count> result{};
    [&]<class... Tr>(detail::type_list<Tr...>) {
      (
          [&] {
            for (const std::size_t s : ends<Tr>::from) {
              if (s != detail::npos) result[s] = true;
            }
          }(),
          ...);
    }(transitions{});
    return result;
  }();
  static constexpr std::array<bool, step_count> reached = [] {
    std::array<bool, step_count> result{};
    result[initial_index] = true;
    for (std::size_t round = 0; round < step_count; ++round) {
      [&]<class... Tr>(detail::type_list<Tr...>) {
        (
            [&] {
              bool any = false;
              for (const std::size_t s : ends<Tr>::from) any = any || (s != detail::npos && result[s]);
              if (!any) return;
              for (const std::size_t s : ends<Tr>::to) {
                if (s != detail::npos) result[s] = true;
              }
            }(),
            ...);
      }(transitions{});
    }
    return result;
  }();

  template <std::size_t I>
  static consteval bool check_step_links() {
    using S = step_at<I>;
    constexpr bool final = []<class... It>(detail::type_list<It...>) {
      return ((It::iecoop_sfc_element == detail::element_kind::final_mark) || ...);
    }(typename S::items{});
    if constexpr (!left[I] && !final) detail::step_never_left<S::member>();
    if constexpr (!reached[I]) detail::step_unreachable<S::member>();
    return true;
  }

  static constexpr bool checked = [] {
    bool ok = true;
    [&]<std::size_t... I>(std::index_sequence<I...>) {
      ((ok = check_step<I>() && ok), ...);
    }(std::make_index_sequence<step_count>{});
    [&]<class... Tr>(detail::type_list<Tr...>) { ((ok = check_transition<Tr>() && ok), ...); }(transitions{});
    [&]<std::size_t... I>(std::index_sequence<I...>) {
      ((ok = check_action<action_at<I>>() && ok), ...);
    }(std::make_index_sequence<action_count>{});
    [&]<std::size_t... I>(std::index_sequence<I...>) {
      ((ok = check_step_links<I>() && ok), ...);
    }(std::make_index_sequence<step_count>{});
    return ok;
  }();

  // The order in which the transitions are tested: by priority, then as declared.
  static constexpr std::array<std::size_t, transition_count> transition_order = [] {
    std::array<std::size_t, transition_count> result{};
    std::array<int, transition_count> priority{};
    [&]<std::size_t... I>(std::index_sequence<I...>) {
      ((result[I] = I, priority[I] = transition_at<I>::priority), ...);
    }(std::make_index_sequence<transition_count>{});
    for (std::size_t i = 1; i < transition_count; ++i) {  // stable insertion sort
      for (std::size_t j = i; j > 0 && priority[result[j]] < priority[result[j - 1]]; --j) {
        std::swap(result[j], result[j - 1]);
      }
    }
    return result;
  }();

  // The names.
  template <std::size_t I>
  static constexpr std::string_view step_name = iecoop::member_name<step_at<I>::member>;
  template <std::size_t I>
  static constexpr std::string_view action_name =
      iecoop::detail::name_in_signature(iecoop::detail::signature_of<action_at<I>>());

  // The order in which the actions run: alphabetical in CODESYS, as associated in matiec.
  static constexpr std::array<std::size_t, action_count> action_order = [] {
    std::array<std::size_t, action_count> result{};
    std::array<std::string_view, action_count> names{};
    [&]<std::size_t... I>(std::index_sequence<I...>) {
      ((result[I] = I, names[I] = action_name<I>), ...);
    }(std::make_index_sequence<action_count>{});
    if constexpr (order::actions_first) {
      for (std::size_t i = 1; i < action_count; ++i) {
        for (std::size_t j = i; j > 0 && names[result[j]] < names[result[j - 1]]; --j) {
          std::swap(result[j], result[j - 1]);
        }
      }
    }
    return result;
  }();

 public:
  // --- SFC flags (CODESYS) ---------------------------------------------------------------
  // SFCInit, SFCReset, SFCPause, SFCError, SFCEnableLimit, SFCQuitError, SFCTip and SFCTipMode
  // are detail::sfc_flags', the chart's base; the chart writes these:
  read_only<BOOL, detail::engine_access> SFCTrans;          ///< a transition fired in this scan
  read_only<STRING<>, detail::engine_access> SFCErrorStep;  ///< the step that set SFCError
  read_only<STRING<>, detail::engine_access> SFCErrorPOU;   ///< the POU of that step
  step_name_view SFCCurrentStep;                            ///< the active step (of several: the last declared)

  chart() noexcept { static_assert(checked); }

  /// One scan of the chart on `pou` (the POU the chart is a member of), at the cycle clock's time.
  void operator()(POU& pou) {
    static_assert(iecoop::detail::none<typename detail::first_non_bool_condition<POU, transitions>::type>,
                  "iecoop: a TRANSITION's condition is a BOOL; the callable of the transition in none<...> (named by "
                  "its FROM and TO steps) yields a number or another type — compare it: [](auto& p) { return "
                  "p.nCount != 0; } (ST: nCount <> 0)");
    static_assert(checked);
    const TIME now = cycle_clock::now_as<TIME>();
    if constexpr (codesys_compiled) {
      // No flag set (the usual scan): one call, of the function the last scan chose (state_:
      // something held has a function of its own).
      if (!any_scan_flag()) [[likely]] {
        const TIME elapsed = TIME(now - last_);
        last_ = now;
        detail::engine_access::ref(SFCTrans) = FALSE;
        state_functions<>::codesys_table[state_](*this, pou, elapsed);
        return;
      }
      scan_with_flags(pou, now);
      return;
    }
    // Nothing held and no flag set (the usual scan): the engine's byte, then the six flags.
    if (held_ == 0 && !any_scan_flag()) [[likely]] {
      const TIME elapsed = TIME(now - last_);
      last_ = now;
      detail::engine_access::ref(SFCTrans) = FALSE;
      scan_usual(pou, elapsed);
      return;
    }
    scan_with_flags(pou, now);
  }

  /// The control of an IEC action of the chart: `chart.action<&P::A_FILL>().Q`.
  template <auto Action>
  [[nodiscard]] const action_state& action() const noexcept {
    constexpr std::size_t index = action_index<Action>();
    static_assert(index != detail::npos, "iecoop: this action is not associated with any step of the chart");
    return states_[index];
  }

  /// The chart's steps, as declared: members of the POU (`pou.*chart.step_members()[0]`).
  [[nodiscard]] static constexpr std::array<sfc::step POU::*, step_count> step_members() noexcept { return members; }

  /// The names of the chart's steps, as declared.
  [[nodiscard]] static constexpr std::array<std::string_view, step_count> step_names() noexcept {
    return []<std::size_t... I>(std::index_sequence<I...>) {
      return std::array<std::string_view, step_count>{step_name<I>...};
    }(std::make_index_sequence<step_count>{});
  }

 private:
  template <auto Action>
  static consteval std::size_t action_index() {
    std::size_t result = detail::npos;
    [&]<std::size_t... I>(std::index_sequence<I...>) {
      ((std::is_same_v<detail::action_tag<Action>, detail::at_t<I, actions>> ? (result = I) : 0), ...);
    }(std::make_index_sequence<action_count>{});
    return result;
  }

  template <std::size_t I>
  static sfc::step& step_of(POU& pou) noexcept {
    return pou.*(members[I]);
  }
  template <std::size_t I>
  static BOOL& X(POU& pou) noexcept {
    return detail::engine_access::ref(step_of<I>(pou).X);
  }
  template <std::size_t I>
  static TIME& T(POU& pou) noexcept {
    return detail::engine_access::ref(step_of<I>(pou).T);
  }
#pragma push_macro("_X")
#undef _X
  template <std::size_t I>
  static BOOL& X_next(POU& pou) noexcept {
    return detail::engine_access::ref(step_of<I>(pou)._X);
  }
#pragma pop_macro("_X")

  template <class F>
  static void each_step(F&& f) {
    [&]<std::size_t... I>(std::index_sequence<I...>) {
      (f(std::integral_constant<std::size_t, I>{}), ...);
    }(std::make_index_sequence<step_count>{});
  }

  // --- Bit sets (sfc/detail/bit_set.hpp) ----------------------------------------------------
  // The engine keeps the active steps, the step events of the scan and the actions' Q as bit
  // sets, so that a scan costs per active step and per running action, not per element.
  template <std::size_t N>
  using bits = detail::bits<N>;

  using step_set = bits<step_count>;
  using action_set = bits<action_count>;

  // Actions are numbered by their rank in the run order (alphabetical in codesys).
  static constexpr std::array<std::size_t, action_count> rank_of = [] {
    std::array<std::size_t, action_count> result{};
    for (std::size_t k = 0; k < action_count; ++k) result[action_order[k]] = k;
    return result;
  }();

  // Per step: the actions associated with it (their controls change when the step does).
  static constexpr std::array<action_set, step_count> step_action_mask = [] {
    std::array<action_set, step_count> result{};
    [&]<std::size_t... I>(std::index_sequence<I...>) {
      (
          [&] {
            []<class... It>(detail::type_list<It...>, action_set& mask) {
              (
                  [&] {
                    if constexpr (It::iecoop_sfc_element == detail::element_kind::association) {
                      detail::set_bit<action_count>(mask, rank_of[action_index<It::action>()]);
                    }
                  }(),
                  ...);
            }(typename step_at<I>::items{}, result[I]);
          }(),
          ...);
    }(std::make_index_sequence<step_count>{});
    return result;
  }();

  // --- Reset ------------------------------------------------------------------------------
  void restart(POU& pou) {
    hold(not_started, false);
    next_state_ = 0;  // the initial step's state (codesys: the state its pending activation leads to)
    if constexpr (!codesys_compiled) state_ = 0;  // (codesys: the scan sets it, index_after_general)
    each_step([&](auto i) {
      constexpr std::size_t I = decltype(i)::value;
      const bool initial = I == initial_index;
      X<I>(pou) = BOOL(initial);
      X_next<I>(pou) = BOOL(initial);
      T<I>(pou) = TIME{};
    });
    active_ = step_set{};
    detail::set_bit<step_count>(active_, initial_index);
    entered_ = left_ = activated_ = deactivated_ = step_set{};
    detail::set_bit<step_count>(entered_, initial_index);  // its activation is seen by the next scan
    for (std::size_t a = 0; a < action_count; ++a) {
      controls_[a] = detail::control{};
      detail::engine_access::ref(states_[a].Q) = FALSE;
      detail::engine_access::ref(states_[a].A) = FALSE;
    }
    q_ = final_ = pulsed_ = timing_ = action_set{};
    [&]<std::size_t... A>(std::index_sequence<A...>) {
      ((detail::bool_member<std::remove_cv_t<decltype(action_at<A>)>>::value
            ? void(set_variable<action_at<A>>(pou, false))
            : void()),
       ...);
    }(std::make_index_sequence<action_count>{});
    SFCError = FALSE;
    text(SFCErrorStep, "");
    text(SFCErrorPOU, "");
    detail::engine_access::ref(SFCTrans) = FALSE;
    hold(quit_held, false);
    detail::engine_access::name(SFCCurrentStep, step_name<initial_index>);
  }

  static void text(read_only<STRING<>, detail::engine_access>& variable, std::string_view value) noexcept {
    detail::engine_access::ref(variable).assign(value);
  }

  template <auto Variable>
  static void set_variable(POU& pou, bool value) {
    if constexpr (detail::bool_member<std::remove_cv_t<decltype(Variable)>>::value) pou.*Variable = BOOL(value);
  }

  void restart_active_times(POU& pou) {
    each_step([&](auto i) {
      constexpr std::size_t I = decltype(i)::value;
      if (X<I>(pou)) T<I>(pou) = TIME{};
    });
  }

  // --- Step evolution ---------------------------------------------------------------------
  template <class It>
  static constexpr detail::step_action_kind step_action_kind_of() {
    if constexpr (It::iecoop_sfc_element == detail::element_kind::step_action) {
      return It::kind;
    } else {
      return detail::step_action_kind::entry;
    }
  }

  template <class F>
  static constexpr auto step_table(F) {
    return []<std::size_t... I>(std::index_sequence<I...>) {
      return std::array<void (*)(chart&, POU&, TIME), step_count>{&F::template call<I>...};
    }(std::make_index_sequence<step_count>{});
  }

  // codesys: the steps the last cycle's transitions activated (X := _X, T := 0) or left.
  struct apply_pending {
    template <std::size_t I>
    static void call(chart& c, POU& pou, TIME) {
      const bool active = X_next<I>(pou);
      X<I>(pou) = BOOL(active);
      if (detail::test_bit<step_count>(c.activated_, I)) T<I>(pou) = TIME{};
      if (active) {
        detail::set_bit<step_count>(c.active_, I);
      } else {
        detail::clear_bit<step_count>(c.active_, I);
      }
    }
  };
  // matiec: the transitions of this scan take effect now.
  struct apply_left {
    template <std::size_t I>
    static void call(chart&, POU& pou, TIME) {
      X<I>(pou) = FALSE;
      X_next<I>(pou) = FALSE;
    }
  };
  struct apply_entered {
    template <std::size_t I>
    static void call(chart&, POU& pou, TIME) {
      X<I>(pou) = TRUE;
      X_next<I>(pou) = TRUE;
      T<I>(pou) = TIME{};
    }
  };
  // An active step's time advances (not in the scan of its activation).
  struct advance_time {
    template <std::size_t I>
    static void call(chart& c, POU& pou, TIME elapsed) {
      if (!detail::test_bit<step_count>(c.activated_, I)) T<I>(pou) = T<I>(pou) + elapsed;
    }
  };
  struct exit_actions {
    template <std::size_t I>
    static void call(chart& c, POU& pou, TIME) {
      c.template step_actions_of<I, detail::step_action_kind::exit>(pou);
    }
  };
  struct entry_actions {
    template <std::size_t I>
    static void call(chart& c, POU& pou, TIME) {
      c.template step_actions_of<I, detail::step_action_kind::entry>(pou);
    }
  };
  // An active step: its maximum time, its CODESYS step action, and which action controls read its time.
  // Mark false: the caller computes those controls itself (scan_codesys_usual).
  struct active_step {
    template <std::size_t I, bool Mark = true>
    static void call(chart& c, POU& pou, TIME elapsed) {
      constexpr TIME maximum = time_limit_of<I, true>();
      if constexpr (maximum != TIME{}) {
        if (T<I>(pou) > maximum && c.SFCEnableLimit && !c.SFCError) {
          c.SFCError = TRUE;
          text(c.SFCErrorStep, step_name<I>);
          text(c.SFCErrorPOU, iecoop::detail::short_type_name<POU>());
        }
      }
      c.template step_actions_of<I, detail::step_action_kind::active>(pou);
      // An L, D or DS association changes its action's Q only in the scan the step's time
      // reaches its duration (or at an activation or deactivation, marked elsewhere).
      [&]<class... It>(detail::type_list<It...>) {
        (
            [&] {
              if constexpr (It::iecoop_sfc_element == detail::element_kind::association) {
                if constexpr (Mark &&
                              (It::kind == qualifier::L || It::kind == qualifier::D || It::kind == qualifier::DS)) {
                  if (TIME(T<I>(pou) - elapsed) < It::duration) {
                    detail::set_bit<action_count>(c.dirty_, rank_of[action_index<It::action>()]);
                  }
                }
              }
            }(),
            ...);
      }(typename step_at<I>::items{});
    }
  };
  struct advance_and_check {
    template <std::size_t I>
    static void call(chart& c, POU& pou, TIME elapsed) {
      advance_time::template call<I>(c, pou, elapsed);
      active_step::template call<I>(c, pou, elapsed);
    }
  };
  // Whether some step has a CODESYS "active" step action (code that may read other steps' times).
  template <detail::step_action_kind K>
  static constexpr bool has_step_actions = [] {
    bool result = false;
    [&]<class... S>(detail::type_list<S...>) {
      (
          [&]<class... It>(detail::type_list<It...>) {
            ((result = result ||
                       (It::iecoop_sfc_element == detail::element_kind::step_action && step_action_kind_of<It>() == K)),
             ...);
          }(typename S::items{}),
          ...);
    }(steps{});
    return result;
  }();
  static constexpr bool has_active_actions = has_step_actions<detail::step_action_kind::active>;
  static constexpr auto advance_and_check_table = step_table(advance_and_check{});
  static constexpr auto apply_pending_table = step_table(apply_pending{});
  static constexpr auto apply_left_table = step_table(apply_left{});
  static constexpr auto apply_entered_table = step_table(apply_entered{});
  static constexpr auto advance_time_table = step_table(advance_time{});
  static constexpr auto exit_table = step_table(exit_actions{});
  static constexpr auto entry_table = step_table(entry_actions{});
  static constexpr auto active_table = step_table(active_step{});

  // The step actions and time checks of the scan, then the actions' controls are marked to be
  // recomputed where a step changed.
  void steps_of_scan(POU& pou, TIME elapsed) {
    detail::for_each_bit<step_count>(deactivated_, exit_table, *this, pou, elapsed);
    detail::for_each_bit<step_count>(activated_, entry_table, *this, pou, elapsed);
    detail::for_each_bit<step_count>(active_, active_table, *this, pou, elapsed);
    mark_changed_steps_actions();
  }

  // The controls of the actions of the steps activated or deactivated in this scan are computed.
  void mark_changed_steps_actions() noexcept {
    for (std::size_t v = 0; v < activated_.size(); ++v) {
      for (std::uint64_t m = activated_[v] | deactivated_[v]; m != 0; m &= m - 1) {
        const action_set& mask = step_action_mask[v * 64 + static_cast<std::size_t>(std::countr_zero(m))];
        for (std::size_t w = 0; w < dirty_.size(); ++w) dirty_[w] |= mask[w];
      }
    }
  }

  // --- Transitions ------------------------------------------------------------------------
  // A transition's source steps as a bit set.
  template <std::size_t Tr>
  static constexpr step_set sources = [] {
    step_set result{};
    for (const std::size_t s : ends<transition_at<Tr>>::from) {
      if (s != detail::npos) detail::set_bit<step_count>(result, s);  // a step not in the chart: reported by `checked`
    }
    return result;
  }();

  // Each transition belongs to its first source step (the lowest-numbered), and a scan tests
  // only the transitions of the active steps, step by step, each step's in test order. That is
  // the test order itself unless a transition shares a source with one tested before it that
  // belongs to a later step; such a chart is tested transition by transition.
  template <std::size_t Tr>
  static constexpr std::size_t home = [] {
    std::size_t result = detail::npos;
    for (const std::size_t s : ends<transition_at<Tr>>::from) result = s < result ? s : result;
    return result;
  }();
  static constexpr bool by_step = [] {
    bool ok = true;
    [&]<std::size_t... K>(std::index_sequence<K...>) {
      const std::array<std::size_t, transition_count> homes{home<transition_order[K]>...};
      const std::array<step_set, transition_count> from{sources<transition_order[K]>...};
      for (std::size_t a = 0; a < transition_count; ++a) {
        for (std::size_t b = a + 1; b < transition_count; ++b) {
          bool shared = false;
          for (std::size_t w = 0; w < from[a].size(); ++w) shared = shared || (from[a][w] & from[b][w]) != 0;
          if (shared && homes[a] > homes[b]) ok = false;
        }
      }
    }(std::make_index_sequence<transition_count>{});
    return ok;
  }();
  struct fire_group {
    template <std::size_t I>
    static void call(chart& c, POU& pou, bool tip) {
      [&]<std::size_t... K>(std::index_sequence<K...>) {
        ((home<transition_order[K]> == I ? void(c.template try_fire<transition_order[K]>(pou, tip)) : void()), ...);
      }(std::make_index_sequence<transition_count>{});
    }
  };
  static constexpr auto fire_table = []<std::size_t... I>(std::index_sequence<I...>) {
    return std::array<void (*)(chart&, POU&, bool), step_count>{&fire_group::template call<I>...};
  }(std::make_index_sequence<step_count>{});

  void fire(POU& pou, bool tip) {
    if (SFCTipMode && !tip) return;
    if constexpr (by_step) {
      detail::for_each_bit<step_count>(active_, fire_table, *this, pou, tip);
    } else {
      [&]<std::size_t... K>(std::index_sequence<K...>) {
        (void(try_fire<transition_order[K]>(pou, tip)), ...);
      }(std::make_index_sequence<transition_count>{});
    }
  }

  // Whether every step a transition names is a step of the chart (if not, `checked` says so).
  template <std::size_t Tr>
  static constexpr bool ends_valid = [] {
    bool ok = true;
    for (const std::size_t s : ends<transition_at<Tr>>::from) ok = ok && s != detail::npos;
    for (const std::size_t s : ends<transition_at<Tr>>::to) ok = ok && s != detail::npos;
    return ok;
  }();

  // Whether transition Tr fired.
  template <std::size_t Tr>
  bool try_fire(POU& pou, bool tip) {
    if constexpr (ends_valid<Tr>) {
      return try_fire_valid<Tr>(pou, tip);
    } else {
      return false;
    }
  }

  // The compiled engine knows which sources are active (Active false) and, where no other
  // transition of the state shares a source, that none was left (Left false); it scans only
  // outside the tip mode (tip false: the flags' scans are the general engine's).
  template <std::size_t Tr, bool Active = true, bool Left = true>
  bool try_fire_valid(POU& pou, bool tip) {
    using E = ends<transition_at<Tr>>;
    // Enabled: every source step active (at the start of the scan) and not left by a
    // transition tested before this one; each source's minimum time reached.
    constexpr step_set from = sources<Tr>;
    for (std::size_t w = 0; w < from.size(); ++w) {
      if constexpr (Active) {
        if ((active_[w] & from[w]) != from[w]) return false;
      }
      if constexpr (Left) {
        if ((left_[w] & from[w]) != 0) return false;
      }
    }
    const bool timed = [&]<std::size_t... F>(std::index_sequence<F...>) {
      return (min_time_reached<E::from[F]>(pou) && ...);
    }(std::make_index_sequence<E::from.size()>{});
    if (!timed) return false;
    if (!SFCTipMode || !tip) {
      if (!detail::test<transition_at<Tr>::condition>(pou)) return false;
    }
    if constexpr (!built_for_size) {
      take_transition_apart<Tr>(pou);
    } else {
      take_transition<Tr>(pou);  // -Os: inline, 72 bytes less of the SFC example on the Cortex-M3
    }
    return true;
  }

  // Transition Tr fires. Apart, and not inlined, where the build is for speed: a scan in which
  // nothing fires (the usual one) then makes no call of its own and saves fewer registers
  // (general engine 305.7 -> 297.1 instructions a scan of the benchmark's chart, g++ 12).
  template <std::size_t Tr>
  [[gnu::noinline]] void take_transition_apart(POU& pou) {
    take_transition<Tr>(pou);
  }
  template <std::size_t Tr>
  void take_transition(POU& pou) {
    using E = ends<transition_at<Tr>>;
    constexpr step_set from = sources<Tr>;
    detail::engine_access::ref(SFCTrans) = TRUE;
    for (std::size_t w = 0; w < from.size(); ++w) left_[w] |= from[w];
    if constexpr (order::actions_first) {
      [&]<std::size_t... F>(std::index_sequence<F...>) {
        ((X_next<E::from[F]>(pou) = FALSE), ...);
      }(std::make_index_sequence<E::from.size()>{});
    }
    [&]<std::size_t... G>(std::index_sequence<G...>) {
      (activate<E::to[G]>(pou), ...);
    }(std::make_index_sequence<E::to.size()>{});
  }

  template <std::size_t I>
  void activate(POU& pou) {
    // Unsafe: the step is active and stays so (no firing transition leaves it), or two
    // transitions activate it in one scan.
    if (detail::test_bit<step_count>(entered_, I) ||
        (detail::test_bit<step_count>(active_, I) && !detail::test_bit<step_count>(left_, I))) {
      fault(fault_kind::unsafe_chart,
            "an SFC transition activated a step that is active already (alternative branches that both lead into "
            "one sequence); the step stays active once");
    }
    detail::set_bit<step_count>(entered_, I);
    if constexpr (order::actions_first) X_next<I>(pou) = TRUE;
  }

  template <std::size_t I>
  bool min_time_reached(POU& pou) const {
    constexpr TIME limit = time_limit_of<I, false>();
    if constexpr (limit == TIME{}) {
      return true;
    } else {
      return T<I>(pou) >= limit;
    }
  }

  template <std::size_t I, bool Maximum>
  static consteval TIME time_limit_of() {
    TIME result{};
    []<class... It>(detail::type_list<It...>, TIME& r) {
      (
          [&] {
            if constexpr (It::iecoop_sfc_element == detail::element_kind::time_limit) {
              if constexpr (It::maximum == Maximum) r = It::limit;
            }
          }(),
          ...);
    }(typename step_at<I>::items{}, result);
    return result;
  }

  // SFCCurrentStep: the last declared of the active steps (of none, unchanged).
  void current_step() {
    static constexpr std::array<std::string_view, step_count> names = step_names();
    for (std::size_t w = active_.size(); w-- > 0;) {
      if (active_[w] != 0) {
        detail::engine_access::name(SFCCurrentStep,
                                    names[w * 64 + 63 - static_cast<std::size_t>(std::countl_zero(active_[w]))]);
        return;
      }
    }
  }

  template <std::size_t I, detail::step_action_kind K>
  void step_actions_of(POU& pou) {
    [&]<class... It>(detail::type_list<It...>) {
      (
          [&] {
            if constexpr (It::iecoop_sfc_element == detail::element_kind::step_action) {
              if constexpr (It::kind == K) (pou.*It::action)();
            }
          }(),
          ...);
    }(typename step_at<I>::items{});
  }

  // --- IEC actions ------------------------------------------------------------------------
  struct inputs {
    bool n = false, r = false, p = false, p1 = false, p0 = false, s = false, l = false, d = false;
    bool sd = false, ds = false, sl = false;
    TIME sd_pt{}, sl_pt{};
  };

  // What a control knows of the steps: nothing (unknown_steps: X and the scan's step events are
  // read at run time), or, in the scan after transition Tr fired alone into state N, all of it
  // (known_steps<N, Tr>: N's steps are the active ones, Tr's targets the activated ones and its
  // sources the deactivated ones), so that the inputs of the control are constants but for the
  // steps' times.
  struct unknown_steps {
    static constexpr bool known = false;
  };
  template <std::size_t N, std::size_t Tr>
  struct known_steps {
    static constexpr bool known = true;
    static constexpr bool active(std::size_t i) noexcept { return detail::test_bit<step_count>(states.sets[N], i); }
    static constexpr bool activated(std::size_t i) noexcept { return detail::test_bit<step_count>(all_targets[Tr], i); }
    static constexpr bool deactivated(std::size_t i) noexcept {
      return detail::test_bit<step_count>(all_sources[Tr], i);
    }
  };

  // ... or, in a scan of state M without step changes, its steps (none activated or deactivated).
  template <std::size_t M>
  struct known_state {
    static constexpr bool known = true;
    static constexpr bool active(std::size_t i) noexcept { return detail::test_bit<step_count>(states.sets[M], i); }
    static constexpr bool activated(std::size_t) noexcept { return false; }
    static constexpr bool deactivated(std::size_t) noexcept { return false; }
  };

  // The qualifiers action A is associated with, as a mask of bits 1 << qualifier.
  template <std::size_t A>
  static constexpr std::uint16_t qualifiers_of = [] {
    std::uint16_t mask = 0;
    [&]<class... S>(detail::type_list<S...>) {
      (
          [&]<class... It>(detail::type_list<It...>) {
            (
                [&] {
                  if constexpr (It::iecoop_sfc_element == detail::element_kind::association) {
                    if constexpr (std::is_same_v<detail::action_tag<It::action>, detail::at_t<A, actions>>) {
                      mask = static_cast<std::uint16_t>(mask | (1U << static_cast<unsigned>(It::kind)));
                    }
                  }
                }(),
                ...);
          }(typename S::items{}),
          ...);
    }(steps{});
    return mask;
  }();
  template <std::size_t A, qualifier... Q>
  static constexpr bool uses = (((qualifiers_of<A> & (1U << static_cast<unsigned>(Q))) != 0) || ...);

  // The inputs of action A's control: its associations, combined with OR.
  template <std::size_t A, class Known = unknown_steps>
  inputs gather(POU& pou) const {
    inputs in;
    each_of<steps_of_action<A>>([&](auto i) {
      constexpr std::size_t I = decltype(i)::value;
      [&]<class... It>(detail::type_list<It...>) {
        (
            [&] {
              if constexpr (It::iecoop_sfc_element == detail::element_kind::association) {
                if constexpr (std::is_same_v<detail::action_tag<It::action>, detail::at_t<A, actions>>) {
                  gather_one<I, It, Known>(pou, in);
                }
              }
            }(),
            ...);
      }(typename step_at<I>::items{});
    });
    return in;
  }

  // Whether step I was activated (Activated) or deactivated in this scan.
  template <std::size_t I, class Known, bool Activated>
  bool changed_in_scan() const noexcept {
    if constexpr (Known::known) {
      return Activated ? Known::activated(I) : Known::deactivated(I);
    } else {
      return detail::test_bit<step_count>(Activated ? activated_ : deactivated_, I);
    }
  }
  template <std::size_t I, class Known>
  static bool active_now(POU& pou) noexcept {
    if constexpr (Known::known) {
      return Known::active(I);
    } else {
      return X<I>(pou);
    }
  }

  template <std::size_t I, class As, class Known>
  void gather_one(POU& pou, inputs& in) const {
    constexpr qualifier q = As::kind;
    if constexpr (q == qualifier::P) {
      in.p = in.p || changed_in_scan<I, Known, true>();
    } else if constexpr (q == qualifier::P1) {
      in.p1 = in.p1 || changed_in_scan<I, Known, true>();
    } else if constexpr (q == qualifier::P0) {
      in.p0 = in.p0 || changed_in_scan<I, Known, false>();
    } else {
      if (!active_now<I, Known>(pou)) return;
      if constexpr (q == qualifier::N) in.n = true;
      if constexpr (q == qualifier::R) in.r = true;
      if constexpr (q == qualifier::S) in.s = true;
      if constexpr (q == qualifier::L) in.l = in.l || T<I>(pou) < As::duration;
      if constexpr (q == qualifier::D) in.d = in.d || T<I>(pou) >= As::duration;
      if constexpr (q == qualifier::DS) in.ds = in.ds || T<I>(pou) >= As::duration;
      if constexpr (q == qualifier::SD) {
        in.sd = true;
        in.sd_pt = As::duration;
      }
      if constexpr (q == qualifier::SL) {
        in.sl = true;
        in.sl_pt = As::duration;
      }
    }
  }

  // IEC's ACTION_CONTROL for action A (by its rank K in the run order), recomputed where a step
  // changed, a pulse ended, a time runs or a final scan was due: Q, A, and what follows.
  // The parts of the control an action's qualifiers cannot reach are left out (a stored flag no
  // association sets stays FALSE).
  struct control_of {
    template <std::size_t K, class Known = unknown_steps>
    static void call(chart& c, POU& pou, TIME elapsed) {
      constexpr std::size_t A = action_order[K];
      using enum qualifier;
      const inputs in = c.template gather<A, Known>(pou);
      detail::control& s = c.controls_[A];
      // The running delays and limits advance first; then the sets; then R, which wins.
      if constexpr (uses<A, SD>) {
        if (s.sd) s.sd_et = s.sd_et + elapsed;
      }
      if constexpr (uses<A, SL>) {
        if (s.sl) s.sl_et = s.sl_et + elapsed;
      }
      if (in.s) s.s = true;
      if constexpr (uses<A, SD>) {
        if (in.sd && !s.sd) {
          s.sd = true;
          s.sd_et = TIME{};
          s.sd_pt = in.sd_pt;
        }
      }
      if constexpr (uses<A, SL>) {
        if (in.sl && !s.sl) {
          s.sl = true;
          s.sl_et = TIME{};
          s.sl_pt = in.sl_pt;
        }
      }
      if (in.ds) s.ds = true;
      bool q = false;
      bool pulse = false;
      if (in.r) {
        if constexpr (uses<A, S>) s.s = false;
        if constexpr (uses<A, SD>) s.sd = false;
        if constexpr (uses<A, DS>) s.ds = false;
        if constexpr (uses<A, SL>) s.sl = false;
      } else {
        const bool held = in.n || in.p || in.l || in.d || (uses<A, S> && s.s) || (uses<A, DS> && s.ds) ||
                          (uses<A, SD> && s.sd && s.sd_et >= s.sd_pt) || (uses<A, SL> && s.sl && s.sl_et < s.sl_pt);
        pulse = !held && (in.p1 || in.p0);
        q = held || pulse;
      }
      // CODESYS runs an action once more after its Q fell (the final scan), except after a
      // P1 or P0 pulse ("executed once"); a P action so runs twice, as CODESYS documents.
      const bool final_scan = order::actions_first && s.q && !q && !(uses<A, P1, P0> && s.pulse);
      s.q = q;
      if constexpr (uses<A, P1, P0>) s.pulse = pulse;
      if (q) {
        detail::set_bit<action_count>(c.q_, K);
      } else {
        detail::clear_bit<action_count>(c.q_, K);
      }
      if (final_scan && with_body_of<K>) detail::set_bit<action_count>(c.final_, K);
      // Recomputed in the next scan too: after a pulse (its Q falls), while a delay or limit
      // runs, and after a final scan (A falls).
      if (in.p || in.p1 || in.p0 || final_scan) detail::set_bit<action_count>(c.pulsed_, K);
      if constexpr (uses<A, SD, SL>) {
        if (s.sd || s.sl) detail::set_bit<action_count>(c.timing_, K);
      }
      detail::engine_access::ref(c.states_[A].Q) = BOOL(q);
      detail::engine_access::ref(c.states_[A].A) = BOOL(q || final_scan);
      if constexpr (detail::bool_member<std::remove_cv_t<decltype(action_at<A>)>>::value) {
        pou.*action_at<A> = BOOL(q);  // a BOOL variable follows Q, without a final scan
      }
    }
  };
  template <std::size_t K>
  static constexpr bool with_body_of =
      !detail::bool_member<std::remove_cv_t<decltype(action_at<action_order[K]>)>>::value;

  struct body_of {
    template <std::size_t K>
    static void call(POU& pou) {
      constexpr auto action = action_at<action_order[K]>;
      if constexpr (!detail::bool_member<std::remove_cv_t<decltype(action)>>::value) (pou.*action)();
    }
  };
  static constexpr auto control_table = []<std::size_t... K>(std::index_sequence<K...>) {
    return std::array<void (*)(chart&, POU&, TIME), action_count>{&control_of::template call<K>...};
  }(std::make_index_sequence<action_count>{});
  static constexpr auto body_table = []<std::size_t... K>(std::index_sequence<K...>) {
    return std::array<void (*)(POU&), action_count>{&body_of::template call<K>...};
  }(std::make_index_sequence<action_count>{});

  // The actions with a body (ACTIONs; a BOOL variable has none).
  static constexpr action_set with_body = [] {
    action_set result{};
    [&]<std::size_t... K>(std::index_sequence<K...>) {
      ((detail::bool_member<std::remove_cv_t<decltype(action_at<action_order[K]>)>>::value
            ? void()
            : detail::set_bit<action_count>(result, K)),
       ...);
    }(std::make_index_sequence<action_count>{});
    return result;
  }();

  // Compiled engine: what take_dirty takes, but an action qualified N and L alone recomputed in
  // the scan after its final scan only for its A to fall (its Q stays FALSE until one of its
  // steps changes, which marks it) has A := Q without its control.
  action_set take_pending() noexcept {
    take_falls();
    return take_dirty();
  }
  // The first part of take_pending, which also forgets the last scan's final scans.
  void take_falls() noexcept {
    if constexpr (detail::any<action_count>(simple_actions)) {
      for (std::size_t w = 0; w < pulsed_.size(); ++w) {
        const std::uint64_t falls = pulsed_[w] & simple_actions[w] & ~dirty_[w];
        pulsed_[w] &= ~falls;
        for (std::uint64_t m = falls; m != 0; m &= m - 1) {
          const std::size_t a = action_order[w * 64 + static_cast<std::size_t>(std::countr_zero(m))];
          detail::engine_access::ref(states_[a].A) = states_[a].Q;
        }
      }
    }
    final_ = action_set{};
  }
  // The actions whose control this scan recomputes (those marked, those after a pulse, those
  // whose delay or limit runs); the marks and the last scan's final scans are forgotten.
  action_set take_dirty() noexcept {
    for (std::size_t w = 0; w < dirty_.size(); ++w) {
      dirty_[w] |= pulsed_[w] | timing_[w];
      pulsed_[w] = timing_[w] = final_[w] = 0;
    }
    const action_set dirty = dirty_;
    dirty_ = action_set{};
    return dirty;
  }

  void iec_actions(POU& pou, TIME elapsed) {
    if constexpr (action_count > 0) {
      // Every control first, then the bodies: an action body cannot change another's Q mid-scan.
      detail::for_each_bit<action_count>(take_dirty(), control_table, *this, pou, elapsed);
      action_set run = q_;
      for (std::size_t w = 0; w < run.size(); ++w) run[w] &= with_body[w];
      if constexpr (order::actions_first) detail::for_each_bit<action_count>(final_, body_table, pou);
      detail::for_each_bit<action_count>(run, body_table, pou);
    }
  }

  // --- The compiled engine -----------------------------------------------------------------
  // The sets of steps that can be active at once (the chart's states) are found at compile time
  // from the initial step through the transitions. Where there are at most max_states, each
  // state gets functions of its own (scan_codesys_usual<M>, scan_matiec_in<M>) that do what the
  // general scan does with its active steps known: the steps' times, checks and step actions,
  // the transitions to test, in their order, and the bodies of the actions, in their order, with
  // an action qualified N only called in the states where one of its steps is active. A scan is
  // one call through a table of those functions; a state that fired a transition knows the
  // state it leads to. The bodies of the other actions are tested on their Q; the controls are
  // computed as code with the steps known (control_n<K, known_steps<N, Tr>> and known_state<M>:
  // for an action qualified N and L alone, a test of its steps and their times; else
  // control_of) where the state knows them: the steps a transition changed, the L, D and DS
  // durations that run; else through the general code's table. In the codesys order state_ is
  // the index of the next scan's function, which each scan chooses (codesys_index): the usual
  // scan of a state, the same with controls left to compute, the scan after one transition fired
  // alone (an entry, up to max_entries of them: the steps it changed and their actions' controls
  // as code, scan_codesys_entered), the scan after several fired (whose state comes from a
  // table, state_after_table), the general scan, the flags' scan where something is held. A
  // scan with an SFC flag set runs the general scan (scan_compiled_flagged). The state lives
  // beside the general engine's bit sets, which are kept as before: both engines compute the
  // same, scan for scan (tests/sfc_engines, tests/unit/sfc_engines_test.cpp).
  static constexpr std::size_t max_states = 64;

  // Each transition's sources, targets, first source step and whether its steps are all in the
  // chart, as arrays (for the loops of the searches below).
  static constexpr std::array<step_set, transition_count> all_sources =
      []<std::size_t... Tr>(std::index_sequence<Tr...>) {
        return std::array<step_set, transition_count>{sources<Tr>...};
      }(std::make_index_sequence<transition_count>{});
  static constexpr std::array<step_set, transition_count> all_targets =
      []<std::size_t... Tr>(std::index_sequence<Tr...>) {
        const auto targets = []<class Tr_>() {
          step_set result{};
          for (const std::size_t s : ends<Tr_>::to) {
            if (s != detail::npos) detail::set_bit<step_count>(result, s);
          }
          return result;
        };
        return std::array<step_set, transition_count>{targets.template operator()<transition_at<Tr>>()...};
      }(std::make_index_sequence<transition_count>{});
  static constexpr std::array<std::size_t, transition_count> all_homes =
      []<std::size_t... Tr>(std::index_sequence<Tr...>) {
        return std::array<std::size_t, transition_count>{home<Tr>...};
      }(std::make_index_sequence<transition_count>{});
  static constexpr std::array<bool, transition_count> all_valid = []<std::size_t... Tr>(std::index_sequence<Tr...>) {
    return std::array<bool, transition_count>{ends_valid<Tr>...};
  }(std::make_index_sequence<transition_count>{});
  static constexpr bool subset(const step_set& a, const step_set& b) noexcept {
    for (std::size_t w = 0; w < a.size(); ++w) {
      if ((a[w] & ~b[w]) != 0) return false;
    }
    return true;
  }
  static constexpr bool intersect(const step_set& a, const step_set& b) noexcept {
    for (std::size_t w = 0; w < a.size(); ++w) {
      if ((a[w] & b[w]) != 0) return true;
    }
    return false;
  }
  static constexpr step_set after(const step_set& m, const step_set& from, const step_set& to) noexcept {
    step_set result{};
    for (std::size_t w = 0; w < m.size(); ++w) result[w] = (m[w] & ~from[w]) | to[w];
    return result;
  }

  struct state_table {
    std::array<step_set, max_states> sets{};
    std::size_t count = 0;
    bool complete = true;
  };
  static constexpr state_table states = [] {
    state_table t{};
    step_set start{};
    detail::set_bit<step_count>(start, initial_index);
    t.sets[0] = start;
    t.count = 1;
    for (std::size_t i = 0; i < t.count && t.complete; ++i) {
      for (std::size_t tr = 0; tr < transition_count && t.complete; ++tr) {
        if (!all_valid[tr] || !subset(all_sources[tr], t.sets[i])) continue;
        const step_set next = after(t.sets[i], all_sources[tr], all_targets[tr]);
        bool known = false;
        for (std::size_t k = 0; k < t.count && !known; ++k) known = t.sets[k] == next;
        if (known) continue;
        if (t.count == max_states) {
          t.complete = false;
        } else {
          t.sets[t.count++] = next;
        }
      }
    }
    return t;
  }();
#if defined(__OPTIMIZE_SIZE__)
  static constexpr bool built_for_size = true;  // -Os, as a firmware is built
#else
  static constexpr bool built_for_size = false;
#endif
  static constexpr bool compiled_by_default = !built_for_size;  // -Os: the smaller engine
  static constexpr bool compiled =
      states.complete && (split::engine == detail::engine_choice::compiled ||
                          (split::engine == detail::engine_choice::unset && compiled_by_default));

 public:
  /// TRUE where the chart runs on the engine compiled from its states, FALSE on the general
  /// engine (sfc::general_engine); both compute the same (docs/sfc.md, "How a chart is run").
  [[nodiscard]] static constexpr bool runs_compiled() noexcept { return compiled; }

 private:
  static constexpr std::size_t state_count = states.count;
  // No state of the table (a set of steps the search did not find: the general scan runs): the
  // index after the last state, whose entry in the tables of the states' functions is the
  // general scan.
  static constexpr std::uint8_t no_state = static_cast<std::uint8_t>(state_count);
  // codesys: the functions of the scans (state_functions<>::codesys_table), by index: the usual
  // scan of each state (its index), the general scan (no_state), the usual scan of each state
  // with controls of the last scan to compute (pending_base + the state), the scan after the
  // last scan's transitions fired (changed_index: several, or after a general scan), the flags'
  // scan where something is held (held_index), the scan after one transition fired alone
  // (entry_base + its entry).
  static constexpr bool codesys_compiled = compiled && order::actions_first;
  static constexpr std::size_t pending_base = state_count + 1;
  static constexpr std::uint8_t changed_index = static_cast<std::uint8_t>(2 * state_count + 1);
  static constexpr std::uint8_t held_index = static_cast<std::uint8_t>(2 * state_count + 2);
  static constexpr std::size_t entry_base = 2 * state_count + 3;

  // The state of the steps `set` (no_state if none).
  static constexpr std::uint8_t state_of(const step_set& set) noexcept {
    for (std::size_t k = 0; k < state_count; ++k) {
      if (states.sets[k] == set) return static_cast<std::uint8_t>(k);
    }
    return no_state;
  }
  // The state transition Tr leads to from each state, where it fires after others fired in the
  // same scan (the state they led to the index; no_state from no_state). In the codesys order a
  // transition fires on the steps active at the scan's start, its sources left by none of the
  // others, and the next scan's steps are the last values of _X: its step changes follow
  // theirs, in the order they fired.
  template <std::size_t Tr>
  static constexpr std::array<std::uint8_t, state_count + 1> state_after_table = [] {
    std::array<std::uint8_t, state_count + 1> table{};
    table.fill(no_state);
    for (std::size_t m = 0; m < state_count; ++m) {
      table[m] = state_of(after(states.sets[m], all_sources[Tr], all_targets[Tr]));
    }
    return table;
  }();
  // The state transition Tr leads to from state M.
  template <std::size_t M, std::size_t Tr>
  static constexpr std::uint8_t state_after = state_after_table<Tr>[M];

  // A list of indices known at compile time (steps, transitions, action ranks) and its length.
  template <std::size_t N>
  struct index_list {
    std::array<std::size_t, (N == 0 ? 1 : N)> at{};
    std::size_t size = 0;
  };
  // The steps with an association of action A, in step order.
  template <std::size_t A>
  static constexpr index_list<step_count> steps_of_action = [] {
    index_list<step_count> list{};
    for (std::size_t i = 0; i < step_count; ++i) {
      if (detail::test_bit<action_count>(step_action_mask[i], rank_of[A])) list.at[list.size++] = i;
    }
    return list;
  }();
  // What Known says of the steps of action A's associations, as bits (bit j: the j-th of
  // steps_of_action<A>): the control of one action in the states and entries where its steps
  // are the same is one instantiation (compile time).
  template <std::size_t A, std::uint64_t Active, std::uint64_t Activated, std::uint64_t Deactivated>
  struct known_local {
    static constexpr bool known = true;
    static constexpr std::uint64_t bit(std::size_t i) noexcept {
      for (std::size_t j = 0; j < steps_of_action<A>.size; ++j) {
        if (steps_of_action<A>.at[j] == i) return std::uint64_t{1} << j;
      }
      return 0;
    }
    static constexpr bool active(std::size_t i) noexcept { return (Active & bit(i)) != 0; }
    static constexpr bool activated(std::size_t i) noexcept { return (Activated & bit(i)) != 0; }
    static constexpr bool deactivated(std::size_t i) noexcept { return (Deactivated & bit(i)) != 0; }
  };
  // Which: 0 active, 1 activated, 2 deactivated.
  template <std::size_t A, class Known, int Which>
  static constexpr std::uint64_t local_bits() noexcept {
    std::uint64_t bits = 0;
    for (std::size_t j = 0; j < steps_of_action<A>.size; ++j) {
      const std::size_t i = steps_of_action<A>.at[j];
      const bool on = Which == 0 ? Known::active(i) : Which == 1 ? Known::activated(i) : Known::deactivated(i);
      if (on) bits |= std::uint64_t{1} << j;
    }
    return bits;
  }
  template <std::size_t A, class Known>
  using localized = known_local<A, local_bits<A, Known, 0>(), local_bits<A, Known, 1>(), local_bits<A, Known, 2>()>;

  // f(integral_constant<List.at[J]>) for each entry J of List, in order (one instantiation per
  // entry, where a fold over all steps with a test would make one per step and state).
  template <const auto& List, class F>
  static void each_of(F&& f) {
    [&]<std::size_t... J>(std::index_sequence<J...>) {
      (f(std::integral_constant<std::size_t, List.at[J]>{}), ...);
    }(std::make_index_sequence<List.size>{});
  }

  // The steps of state M, in the order of the steps.
  template <std::size_t M>
  static constexpr index_list<step_count> steps_in = [] {
    index_list<step_count> list{};
    for (std::size_t i = 0; i < step_count; ++i) {
      if (detail::test_bit<step_count>(states.sets[M], i)) list.at[list.size++] = i;
    }
    return list;
  }();
  template <std::size_t M, class F>
  static void each_step_in(F&& f) {
    each_of<steps_in<M>>(std::forward<F>(f));
  }

  // Whether the action of rank K is associated with its steps by N alone (only), by N and L
  // alone (simple), with which steps by N, and with which by any qualifier.
  struct association_kinds {
    bool only = true;
    bool simple = true;
    step_set with{};
    step_set any{};
  };
  template <std::size_t I, std::size_t A>
  static constexpr void n_associations_of(association_kinds& k) {
    []<class... It>(detail::type_list<It...>, association_kinds& r) {
      (
          [&] {
            if constexpr (It::iecoop_sfc_element == detail::element_kind::association) {
              if constexpr (std::is_same_v<detail::action_tag<It::action>, detail::at_t<A, actions>>) {
                detail::set_bit<step_count>(r.any, I);
                if constexpr (It::kind == qualifier::N) {
                  detail::set_bit<step_count>(r.with, I);
                } else {
                  r.only = false;
                  r.simple = r.simple && It::kind == qualifier::L;
                }
              }
            }
          }(),
          ...);
    }(typename step_at<I>::items{}, k);
  }
  template <std::size_t K>
  struct n_action {
    static constexpr association_kinds found = [] {
      association_kinds k{};
      [&]<std::size_t... I>(std::index_sequence<I...>) {
        (n_associations_of<I, action_order[K]>(k), ...);
      }(std::make_index_sequence<step_count>{});
      return k;
    }();
    static constexpr bool only = found.only;
    static constexpr bool simple = found.simple;
    static constexpr step_set steps = found.with;
    static constexpr step_set any_steps = found.any;
  };

  // Q of a simple action (N and L only): one of its N steps active, or one of its L steps active
  // for less than its duration.
  template <std::size_t K, class Known = unknown_steps>
  static bool simple_q(POU& pou) {
    constexpr std::size_t A = action_order[K];
    bool q = false;
    [&]<std::size_t... J>(std::index_sequence<J...>) {
      (
          [&] {
            constexpr std::size_t step = steps_of_action<A>.at[J];
            [&]<class... It>(detail::type_list<It...>, POU& p, bool& r) {
              (
                  [&] {
                    if constexpr (It::iecoop_sfc_element == detail::element_kind::association) {
                      if constexpr (std::is_same_v<detail::action_tag<It::action>, detail::at_t<A, actions>>) {
                        if constexpr (It::kind == qualifier::N) {
                          r = r || active_now<step, Known>(p);
                        } else if constexpr (It::kind == qualifier::L) {
                          r = r || (active_now<step, Known>(p) && T<step>(p) < It::duration);
                        }
                      }
                    }
                  }(),
                  ...);
            }(typename step_at<step>::items{}, pou, q);
          }(),
          ...);
    }(std::make_index_sequence<steps_of_action<A>.size>{});
    return q;
  }

  // An action qualified N and L alone: Q is TRUE while one of its N steps is active or one of
  // its L steps is active for less than the duration; a final scan when it falls (codesys). What
  // control_of computes for it, without gathering its inputs.
  struct control_n {
    template <std::size_t K, class Known = unknown_steps>
    static void call(chart& c, POU& pou, TIME elapsed) {
      if constexpr (Known::known && steps_of_action<action_order[K]>.size <= 64) {
        call_as<K, localized<action_order[K], Known>>(c, pou, elapsed);
      } else {
        call_as<K, Known>(c, pou, elapsed);
      }
    }
    template <std::size_t K, class Known>
    static void call_as(chart& c, POU& pou, TIME elapsed) {
      if constexpr (!n_action<K>::simple) {
        control_of::template call<K, Known>(c, pou, elapsed);
      } else {
        constexpr std::size_t A = action_order[K];
        const bool q = simple_q<K, Known>(pou);
        detail::control& s = c.controls_[A];
        const bool final_scan = order::actions_first && s.q && !q;
        s.q = q;
        if (q) {
          detail::set_bit<action_count>(c.q_, K);
        } else {
          detail::clear_bit<action_count>(c.q_, K);
        }
        if (final_scan) {
          if constexpr (with_body_of<K>) detail::set_bit<action_count>(c.final_, K);
          detail::set_bit<action_count>(c.pulsed_, K);
        }
        detail::engine_access::ref(c.states_[A].Q) = BOOL(q);
        detail::engine_access::ref(c.states_[A].A) = BOOL(q || final_scan);
        if constexpr (detail::bool_member<std::remove_cv_t<decltype(action_at<A>)>>::value) {
          pou.*action_at<A> = BOOL(q);
        }
      }
    }
  };
  // The actions qualified N and L alone (control_n computes them without the general control).
  static constexpr action_set simple_actions = [] {
    action_set result{};
    [&]<std::size_t... K>(std::index_sequence<K...>) {
      ((n_action<K>::simple ? detail::set_bit<action_count>(result, K) : void()), ...);
    }(std::make_index_sequence<action_count>{});
    return result;
  }();
  static constexpr auto control_n_table = []<std::size_t... K>(std::index_sequence<K...>) {
    return std::array<void (*)(chart&, POU&, TIME), action_count>{&control_n::template call<K>...};
  }(std::make_index_sequence<action_count>{});

  // SFCCurrentStep in state M: the last declared of its steps.
  template <std::size_t M>
  static constexpr std::string_view current_step_in = [] {
    constexpr std::array<std::string_view, step_count> names = step_names();
    return steps_in<M>.size == 0 ? std::string_view{} : names[steps_in<M>.at[steps_in<M>.size - 1]];
  }();

  // What steps_of_scan does, in state M.
  template <std::size_t M, bool Mark = true>
  void steps_of_scan_in(POU& pou, TIME elapsed, bool changed) {
    if constexpr (has_step_actions<detail::step_action_kind::exit>) {
      detail::for_each_bit<step_count>(deactivated_, exit_table, *this, pou, elapsed);
    }
    if constexpr (has_step_actions<detail::step_action_kind::entry>) {
      // (not only M's steps: in the matiec order a step activated by a reset and left in the
      // same scan has its entry action too)
      detail::for_each_bit<step_count>(activated_, entry_table, *this, pou, elapsed);
    }
    each_step_in<M>([&](auto i) { active_step::template call<decltype(i)::value, Mark>(*this, pou, elapsed); });
    if (changed) {
      mark_changed_steps_actions();
    }
  }

  // What iec_actions does, in state M.
  // The actions with a body that are not N only: their Q is tested at run time.
  static constexpr action_set tested_bodies = [] {
    action_set result{};
    [&]<std::size_t... K>(std::index_sequence<K...>) {
      ((with_body_of<K> && !n_action<K>::only ? detail::set_bit<action_count>(result, K) : void()), ...);
    }(std::make_index_sequence<action_count>{});
    return result;
  }();

  // The ranks whose body state M calls, in run order: the N-only actions with a step in M, the
  // simple ones (N and L) with a step in M and the others with a body, those two with their Q
  // tested at run time. (A simple action's Q is FALSE where none of its steps is active: its
  // control is computed before the bodies in the scan its last step was left, and its final
  // scan runs through final_.)
  template <std::size_t M>
  static constexpr index_list<action_count> bodies_in = [] {
    index_list<action_count> list{};
    [&]<std::size_t... K>(std::index_sequence<K...>) {
      (
          [&] {
            if constexpr (with_body_of<K>) {
              const bool possible = n_action<K>::only     ? intersect(n_action<K>::steps, states.sets[M])
                                    : n_action<K>::simple ? intersect(n_action<K>::any_steps, states.sets[M])
                                                          : true;
              if (possible) list.at[list.size++] = K;
            }
          }(),
          ...);
    }(std::make_index_sequence<action_count>{});
    return list;
  }();

  template <std::size_t M>
  void iec_actions_in(POU& pou, TIME elapsed) {
    if constexpr (action_count > 0) {
      bool pending = false;  // a control to compute, or a final scan of the last scan to forget
      for (std::size_t w = 0; w < dirty_.size(); ++w)
        pending = pending || (dirty_[w] | pulsed_[w] | timing_[w] | final_[w]) != 0;
      if (pending) controls_pending(pou, elapsed);
      run_bodies_in<M>(pou);
    }
  }
  // The controls to compute, and the last scan's final scans. Apart, and not inlined: the usual
  // scan has none.
  [[gnu::noinline]] void controls_pending(POU& pou, TIME elapsed) {
    detail::for_each_bit<action_count>(take_pending(), control_n_table, *this, pou, elapsed);
    if constexpr (order::actions_first) detail::for_each_bit<action_count>(final_, body_table, pou);
  }
  // The bodies state M calls, in run order (bodies_in<M>).
  template <std::size_t M>
  [[gnu::always_inline]] void run_bodies_in(POU& pou) {
    bool tested = false;  // one test for all the actions whose Q is known only at run time
    for (std::size_t w = 0; w < q_.size(); ++w) tested = tested || (q_[w] & tested_bodies[w]) != 0;
    each_of<bodies_in<M>>([&](auto k) {
      constexpr std::size_t K = decltype(k)::value;
      if constexpr (n_action<K>::only) {
        body_of::template call<K>(pou);
      } else {
        if (tested && detail::test_bit<action_count>(q_, K)) body_of::template call<K>(pou);
      }
    });
  }
  // Step I becomes active in this scan: X := TRUE, T := 0.
  template <std::size_t I>
  static void step_entered(POU& pou) {
    X<I>(pou) = TRUE;
    T<I>(pou) = TIME{};
  }
  // The steps of state M are the active ones now.
  template <std::size_t M>
  void state_entered() {
    active_ = states.sets[M];
    if constexpr (steps_in<M>.size > 0) detail::engine_access::name(SFCCurrentStep, current_step_in<M>);
  }

  // The transitions state M tests, in the order fire() tests them (by step, else by priority).
  template <std::size_t M>
  static constexpr index_list<transition_count> candidates_in = [] {
    index_list<transition_count> list{};
    const auto can = [](std::size_t tr) { return all_valid[tr] && subset(all_sources[tr], states.sets[M]); };
    if constexpr (by_step) {
      for (std::size_t i = 0; i < step_count; ++i) {
        if (!detail::test_bit<step_count>(states.sets[M], i)) continue;
        for (std::size_t k = 0; k < transition_count; ++k) {
          if (all_homes[transition_order[k]] == i && can(transition_order[k]))
            list.at[list.size++] = transition_order[k];
        }
      }
    } else {
      for (std::size_t k = 0; k < transition_count; ++k) {
        if (can(transition_order[k])) list.at[list.size++] = transition_order[k];
      }
    }
    return list;
  }();
  // Whether another transition state M tests shares a source step with transition Tr (then one
  // tested before Tr may have left it).
  template <std::size_t M, std::size_t Tr>
  static constexpr bool shares_source = [] {
    for (std::size_t j = 0; j < candidates_in<M>.size; ++j) {
      const std::size_t u = candidates_in<M>.at[j];
      if (u != Tr && intersect(all_sources[u], all_sources[Tr])) return true;
    }
    return false;
  }();

  // What fire does, in state M: the transitions whose sources are all in M, in their order.
  // Where one fires, next_state_ gets the state the scan's firings lead to (a scan in which none
  // fires does not write it: it is read only in the scan after a firing, or after restart(),
  // which sets it). Codesys: returns the index of the next scan's function (codesys_index): the
  // entry of the one transition that fired, the changed scan where several did, else `none`.
  template <std::size_t M>
  std::uint8_t fire_in(POU& pou, std::uint8_t none = 0) {
    std::uint8_t next = none;
    bool fired = false;
    [&]<std::size_t... J>(std::index_sequence<J...>) {
      (
          [&] {
            constexpr std::size_t Tr = candidates_in<M>.at[J];
            if (try_fire_valid<Tr, false, shares_source<M, Tr>>(pou, false)) {
              // (after others: codesys, from the state theirs lead to; matiec, whose scan applies
              // every left step before every entered one, from the steps, no_state)
              next_state_ =
                  fired ? (order::actions_first ? state_after_table<Tr>[next_state_] : no_state) : state_after<M, Tr>;
              if constexpr (order::actions_first) next = fired ? changed_index : entry_index<M, J>;
              fired = true;
            }
          }(),
          ...);
    }(std::make_index_sequence<candidates_in<M>.size>{});
    return next;
  }

  // --- Entries: the scan after one transition fired, its step changes known ------------------
  // The scan after transition Tr (the J-th that state M tests) fired alone knows the steps it
  // activates and deactivates: their X and T, SFCCurrentStep and the controls of their actions
  // are written for those steps, as code, instead of through the bit sets' loops and the
  // controls' table. Only fire_in chooses an entry, where Tr alone fired: then the bit sets say
  // exactly that (a flags' scan in between chooses the next scan's function anew).
  // The first entry of each state (an entry per transition a state tests), and their count.
  static constexpr std::array<std::size_t, max_states + 1> entry_offsets = [] {
    std::array<std::size_t, max_states + 1> offsets{};
    [&]<std::size_t... M>(std::index_sequence<M...>) {
      const std::array<std::size_t, sizeof...(M)> sizes{candidates_in<M>.size...};
      for (std::size_t m = 0; m < sizes.size(); ++m) offsets[m + 1] = offsets[m] + sizes[m];
    }(std::make_index_sequence<state_count>{});
    return offsets;
  }();
  static constexpr std::size_t entry_count = entry_offsets[state_count];
  // Entries are made where the chart has at most 96 (each is a function of its own to compile;
  // and every codesys_index fits a byte: 2 x 64 states + 3 + 96 < 256).
  static constexpr std::size_t max_entries = 96;
  static constexpr bool with_entries = entry_count > 0 && entry_count <= max_entries;
  static constexpr std::size_t codesys_functions = entry_base + (with_entries ? entry_count : 0);
  static_assert(codesys_functions <= 256);
  template <std::size_t M, std::size_t J>
  static constexpr std::uint8_t entry_index =
      with_entries ? static_cast<std::uint8_t>(entry_base + entry_offsets[M] + J) : changed_index;

  // The actions whose controls change where the steps `changed` change (mark_changed_steps_actions).
  static constexpr action_set actions_of_steps(const step_set& changed) noexcept {
    action_set result{};
    for (std::size_t i = 0; i < step_count; ++i) {
      if (!detail::test_bit<step_count>(changed, i)) continue;
      for (std::size_t w = 0; w < result.size(); ++w) result[w] |= step_action_mask[i][w];
    }
    return result;
  }
  template <std::size_t Tr>
  static constexpr action_set actions_changed_by = [] {
    step_set changed{};
    for (std::size_t w = 0; w < changed.size(); ++w) changed[w] = all_sources[Tr][w] | all_targets[Tr][w];
    return actions_of_steps(changed);
  }();
  template <std::size_t Tr>
  static constexpr index_list<action_count> ranks_changed_by = [] {
    index_list<action_count> list{};
    for (std::size_t k = 0; k < action_count; ++k) {
      if (detail::test_bit<action_count>(actions_changed_by<Tr>, k)) list.at[list.size++] = k;
    }
    return list;
  }();
  // The steps transition Tr leaves that are not in state N, and those of N it enters.
  template <std::size_t N, std::size_t Tr>
  static constexpr index_list<step_count> steps_left_by = [] {
    index_list<step_count> list{};
    for (std::size_t i = 0; i < step_count; ++i) {
      if (detail::test_bit<step_count>(all_sources[Tr], i) && !detail::test_bit<step_count>(states.sets[N], i))
        list.at[list.size++] = i;
    }
    return list;
  }();
  template <std::size_t N, std::size_t Tr>
  static constexpr index_list<step_count> steps_entered_by = [] {
    index_list<step_count> list{};
    for (std::size_t i = 0; i < step_count; ++i) {
      if (detail::test_bit<step_count>(all_targets[Tr], i) && detail::test_bit<step_count>(states.sets[N], i))
        list.at[list.size++] = i;
    }
    return list;
  }();

  // The codesys scan in state N after transition Tr fired alone in the last scan: what
  // scan_codesys_in<N> does with `changed`, its step changes written out.
  template <std::size_t N, std::size_t Tr>
  void scan_codesys_entered(POU& pou, TIME elapsed) {
    each_of<steps_left_by<N, Tr>>(
        [&](auto i) { detail::engine_access::ref((pou.*members[decltype(i)::value]).X) = FALSE; });
    each_of<steps_entered_by<N, Tr>>([&](auto i) { step_entered<decltype(i)::value>(pou); });
    state_entered<N>();
    each_step_in<N>([&](auto i) {  // the steps Tr did not enter: their time advances
      constexpr std::size_t I = decltype(i)::value;
      if constexpr (!detail::test_bit<step_count>(all_targets[Tr], I)) T<I>(pou) = T<I>(pou) + elapsed;
    });
    steps_of_scan_in<N, false>(pou, elapsed, false);  // (the L, D and DS durations: below)
    if constexpr (action_count > 0) {
      // The controls of the actions of the steps that changed, each called as itself with the
      // steps known.
      const auto changed_controls = [&] {
        each_of<ranks_changed_by<Tr>>([&](auto k) {
          constexpr std::size_t K = decltype(k)::value;
          control_n::template call<K, known_steps<N, Tr>>(*this, pou, elapsed);
        });
      };
      take_falls();
      if (controls_left()) [[unlikely]] {
        // Besides: controls the last scan left (a pulse ended, a delay or limit runs) and those
        // whose duration runs, through the table, and the final scans in their order.
        mark_windows<N>(pou, elapsed);
        action_set pending = take_dirty();
        changed_controls();
        for (std::size_t w = 0; w < pending.size(); ++w) pending[w] &= ~actions_changed_by<Tr>[w];
        detail::for_each_bit<action_count>(pending, control_n_table, *this, pou, elapsed);
        detail::for_each_bit<action_count>(final_, body_table, pou);
      } else {
        // Besides: the controls whose duration runs, and the final scans, each as itself.
        changed_controls();
        each_of<windows_after<N, Tr>>([&](auto k) {
          constexpr std::size_t K = decltype(k)::value;
          if (window_runs<N, K>(pou, elapsed)) control_n::template call<K, known_steps<N, Tr>>(*this, pou, elapsed);
        });
        each_of<finals_after<N, Tr>>([&](auto k) {
          constexpr std::size_t K = decltype(k)::value;
          if constexpr (with_body_of<K>) {
            if (detail::test_bit<action_count>(final_, K)) body_of::template call<K>(pou);
          }
        });
      }
      run_bodies_in<N>(pou);
    }
    state_ = fire_in<N>(pou, after_controls<N>());
  }

  // The usual codesys scan in state M: no step changed; Pending: controls of the last scan are
  // to be computed (a pulse ended, a final scan was run, a delay or limit runs). The controls
  // whose L, D or DS duration runs are computed with them, or, where nothing else is, as code.
  template <std::size_t M, bool Pending>
  void scan_codesys_usual(POU& pou, TIME elapsed) {
    advance_times_in<M>(elapsed, pou);
    steps_of_scan_in<M, false>(pou, elapsed, false);  // (the L, D and DS durations: below)
    std::uint8_t next = static_cast<std::uint8_t>(M);
    if constexpr (action_count > 0) {
      bool general = false;  // controls of the last scan to compute (not only an A that falls)
      if constexpr (Pending) {
        take_falls();
        general = controls_left();
      }
      next = general ? general_controls_in<M>(pou, elapsed) : window_controls_in<M>(pou, elapsed);
      run_bodies_in<M>(pou);
    }
    state_ = fire_in<M>(pou, next);
  }
  // (The parts of scan_codesys_usual<M, Pending> that do not depend on Pending: one
  // instantiation for both, to compile.)
  template <std::size_t M>
  static void advance_times_in(TIME elapsed, POU& pou) {
    each_step_in<M>([&](auto i) { T<decltype(i)::value>(pou) = T<decltype(i)::value>(pou) + elapsed; });
  }
  // Controls of the last scan to compute: with those whose duration runs, through the table.
  template <std::size_t M>
  std::uint8_t general_controls_in(POU& pou, TIME elapsed) {
    mark_windows<M>(pou, elapsed);
    controls_pending(pou, elapsed);
    return after_controls<M>();
  }
  // Nothing else pending: the controls whose L, D or DS duration runs, each called as itself
  // with M's steps known, then their final scans. The next scan's function.
  template <std::size_t M>
  std::uint8_t window_controls_in(POU& pou, TIME elapsed) {
    if constexpr (window_actions_in<M>.size == 0) {
      return static_cast<std::uint8_t>(M);
    } else {
      bool computed = false;
      each_of<window_actions_in<M>>([&](auto k) {
        constexpr std::size_t K = decltype(k)::value;
        if (window_runs<M, K>(pou, elapsed)) {
          control_n::template call<K, known_state<M>>(*this, pou, elapsed);
          computed = true;
        }
      });
      if (!computed) return static_cast<std::uint8_t>(M);
      each_of<window_actions_in<M>>([&](auto k) {
        constexpr std::size_t K = decltype(k)::value;
        if constexpr (with_body_of<K>) {
          if (detail::test_bit<action_count>(final_, K)) body_of::template call<K>(pou);
        }
      });
      return after_controls<M>();
    }
  }
  // What active_step marks in state M: the controls whose L, D or DS duration runs.
  template <std::size_t M>
  void mark_windows(POU& pou, TIME elapsed) {
    each_of<window_actions_in<M>>([&](auto k) {
      constexpr std::size_t K = decltype(k)::value;
      if (window_runs<M, K>(pou, elapsed)) detail::set_bit<action_count>(dirty_, K);
    });
  }
  // The actions with an L, D or DS association on a step of state M, by rank.
  template <std::size_t M>
  static constexpr index_list<action_count> window_actions_in = [] {
    action_set found{};
    [&]<std::size_t... I>(std::index_sequence<I...>) {
      (
          [&] {
            if (!detail::test_bit<step_count>(states.sets[M], I)) return;
            []<class... It>(detail::type_list<It...>, action_set& r) {
              (
                  [&] {
                    if constexpr (It::iecoop_sfc_element == detail::element_kind::association) {
                      if constexpr (It::kind == qualifier::L || It::kind == qualifier::D || It::kind == qualifier::DS) {
                        detail::set_bit<action_count>(r, rank_of[action_index<It::action>()]);
                      }
                    }
                  }(),
                  ...);
            }(typename step_at<I>::items{}, found);
          }(),
          ...);
    }(std::make_index_sequence<step_count>{});
    index_list<action_count> list{};
    for (std::size_t k = 0; k < action_count; ++k) {
      if (detail::test_bit<action_count>(found, k)) list.at[list.size++] = k;
    }
    return list;
  }();
  // The actions with an L, D or DS duration in state N that transition Tr did not change, and
  // those whose control the scan after Tr computes (changed or running), by rank.
  template <std::size_t N, std::size_t Tr>
  static constexpr index_list<action_count> windows_after = [] {
    index_list<action_count> list{};
    for (std::size_t j = 0; j < window_actions_in<N>.size; ++j) {
      const std::size_t k = window_actions_in<N>.at[j];
      if (!detail::test_bit<action_count>(actions_changed_by<Tr>, k)) list.at[list.size++] = k;
    }
    return list;
  }();
  template <std::size_t N, std::size_t Tr>
  static constexpr index_list<action_count> finals_after = [] {
    index_list<action_count> list{};
    for (std::size_t k = 0; k < action_count; ++k) {
      bool window = false;
      for (std::size_t j = 0; j < windows_after<N, Tr>.size; ++j) window = window || windows_after<N, Tr>.at[j] == k;
      if (window || detail::test_bit<action_count>(actions_changed_by<Tr>, k)) list.at[list.size++] = k;
    }
    return list;
  }();
  // Whether the duration of an L, D or DS association of action K on a step of state M runs in
  // this scan (what active_step marks).
  template <std::size_t M, std::size_t K>
  static bool window_runs(POU& pou, TIME elapsed) {
    bool runs = false;
    each_step_in<M>([&](auto i) {
      constexpr std::size_t I = decltype(i)::value;
      []<class... It>(detail::type_list<It...>, [[maybe_unused]] POU& p, [[maybe_unused]] TIME e, bool& r) {
        (
            [&] {
              if constexpr (It::iecoop_sfc_element == detail::element_kind::association) {
                if constexpr ((It::kind == qualifier::L || It::kind == qualifier::D || It::kind == qualifier::DS) &&
                              rank_of[action_index<It::action>()] == K) {
                  r = r || TIME(T<I>(p) - e) < It::duration;
                }
              }
            }(),
            ...);
      }(typename step_at<I>::items{}, pou, elapsed, runs);
    });
    return runs;
  }
  // The codesys scan in state M after the last scan's transitions fired (not one alone, or after
  // a general scan): the step changes from the bit sets.
  template <std::size_t M>
  void scan_codesys_changed_in(POU& pou, TIME elapsed) {
    steps_changed_in<M>(pou);
    each_step_in<M>([&](auto i) { advance_time::template call<decltype(i)::value>(*this, pou, elapsed); });
    steps_of_scan_in<M>(pou, elapsed, false);  // (the changed steps' actions: marked above)
    iec_actions_in<M>(pou, elapsed);
    state_ = fire_in<M>(pou, after_controls<M>());
  }
  // Whether controls are left to compute in the next scan: a pulse ends, A falls after a final
  // scan, a delay or a limit runs.
  [[nodiscard]] bool controls_left() const noexcept {
    bool any = false;
    for (std::size_t w = 0; w < pulsed_.size(); ++w) any = any || (pulsed_[w] | timing_[w]) != 0;
    return any;
  }
  // The next scan's function in state M where no transition fires (codesys_index).
  template <std::size_t M>
  std::uint8_t after_controls() const noexcept {
    if constexpr (action_count == 0) {
      return static_cast<std::uint8_t>(M);
    } else {
      return controls_left() ? static_cast<std::uint8_t>(pending_base + M) : static_cast<std::uint8_t>(M);
    }
  }
  // What apply_pending does, M's steps known: X := _X, T := 0 where activated; the actions of
  // the steps that changed are marked (mark_changed_steps_actions). Apart, and not inlined: the
  // usual scan changes no step.
  template <std::size_t M>
  [[gnu::noinline]] void steps_changed_in(POU& pou) {
    for (std::size_t w = 0; w < deactivated_.size(); ++w) {
      for (std::uint64_t m = deactivated_[w] & ~states.sets[M][w]; m != 0; m &= m - 1) {
        detail::engine_access::ref((pou.*members[w * 64 + static_cast<std::size_t>(std::countr_zero(m))]).X) = FALSE;
      }
      // A step one transition entered and a later one left (several fired): its time restarts.
      for (std::uint64_t m = activated_[w] & ~states.sets[M][w]; m != 0; m &= m - 1) {
        detail::engine_access::ref((pou.*members[w * 64 + static_cast<std::size_t>(std::countr_zero(m))]).T) = TIME{};
      }
    }
    each_step_in<M>([&](auto i) {
      constexpr std::size_t I = decltype(i)::value;
      if (detail::test_bit<step_count>(activated_, I)) step_entered<I>(pou);
    });
    state_entered<M>();
    mark_changed_steps_actions();
  }

  // The matiec scan in state M, after scan_matiec's first lines; where a transition fired, the
  // rest of the scan runs in the state it led to.
  template <std::size_t M>
  void scan_matiec_in(POU& pou, TIME elapsed) {
    each_step_in<M>([&](auto i) { advance_time::template call<decltype(i)::value>(*this, pou, elapsed); });
    fire_in<M>(pou);
    if (SFCTrans) {
      apply_matiec_evolution(pou, elapsed);
      state_ = next_state_ != no_state ? next_state_ : state_of(active_);
      if (state_ == no_state) {
        steps_of_scan(pou, elapsed);
        iec_actions(pou, elapsed);
      } else {
        state_functions<>::rest[state_](*this, pou, elapsed);
      }
      return;
    }
    rest_matiec_in<M>(pou, elapsed);
  }
  template <std::size_t M>
  void rest_matiec_in(POU& pou, TIME elapsed) {
    const bool changed = detail::any<step_count>(activated_) || detail::any<step_count>(deactivated_);
    steps_of_scan_in<M>(pou, elapsed, changed);
    iec_actions_in<M>(pou, elapsed);
  }

  // The tables of the states' functions (instantiated only for a compiled chart), each with one
  // entry more, at no_state: the general scan; in the codesys order one table of every scan's
  // function, by codesys_index. They run the scans outside the tip mode (a scan with an SFC flag
  // set runs on the general engine: scan_compiled_flagged).
  template <bool = true>
  struct state_functions {
    using scan_function = void (*)(chart&, POU&, TIME);

    // --- matiec: the state of the active steps is state_ (no_state: the general scan) ---
    template <std::size_t M>
    static void scan_matiec(chart& c, POU& pou, TIME elapsed) {
      c.template scan_matiec_in<M>(pou, elapsed);
    }
    static void scan_matiec_general(chart& c, POU& pou, TIME elapsed) { c.scan_matiec_rest(pou, elapsed, false); }
    template <std::size_t M>
    static void rest_of(chart& c, POU& pou, TIME elapsed) {
      c.template rest_matiec_in<M>(pou, elapsed);
    }
    static constexpr auto matiec_scans = []<std::size_t... M>(std::index_sequence<M...>) {
      return std::array<scan_function, state_count + 1>{&scan_matiec<M>..., &scan_matiec_general};
    }(std::make_index_sequence<state_count>{});
    static constexpr auto rest = []<std::size_t... M>(std::index_sequence<M...>) {
      return std::array<scan_function, state_count>{&rest_of<M>...};
    }(std::make_index_sequence<state_count>{});

    // --- codesys: state_ is the index of the next scan's function (codesys_index) ---
    template <std::size_t M, bool Pending>
    static void usual(chart& c, POU& pou, TIME elapsed) {
      c.template scan_codesys_usual<M, Pending>(pou, elapsed);
    }
    // The general scan, where the active steps are no state of the table.
    static void general(chart& c, POU& pou, TIME elapsed) {
      c.scan_codesys_rest(pou, elapsed, false);
      c.forget_next_state();
      c.state_ = c.index_after_general();
    }
    template <std::size_t M>
    static void changed_in(chart& c, POU& pou, TIME elapsed) {
      c.template scan_codesys_changed_in<M>(pou, elapsed);
    }
    static constexpr auto changed_scans = []<std::size_t... M>(std::index_sequence<M...>) {
      return std::array<scan_function, state_count + 1>{&changed_in<M>..., &general};
    }(std::make_index_sequence<state_count>{});
    // The scan after the last scan's transitions fired (several, or after a general scan): the
    // state from the one the firings led to, else from the steps.
    static void changed(chart& c, POU& pou, TIME elapsed) {
      c.take_step_events();
      std::uint8_t m = c.next_state_;
      if (m == no_state) m = c.state_after_several(pou);
      changed_scans[m](c, pou, elapsed);
      c.activated_ = c.deactivated_ = step_set{};  // (empty between scans)
    }
    // Something held (not started, SFCQuitError's hold, SFCTip's last value): the flags' scan.
    static void held(chart& c, POU& pou, TIME elapsed) { c.scan_flagged(pou, c.started() ? elapsed : TIME{}); }
    // The scan after the J-th transition state M tests fired alone: its step changes known.
    template <std::size_t M, std::size_t J>
    static void entered(chart& c, POU& pou, TIME elapsed) {
      constexpr std::size_t Tr = candidates_in<M>.at[J];
      constexpr std::uint8_t N = state_after<M, Tr>;
      if constexpr (N == no_state) {
        changed(c, pou, elapsed);
      } else {
        // What the last scan's firing left: Tr's targets entered, its sources left (fire_in
        // makes this index only so); step actions read them as the scan's step events.
        constexpr bool events_read =
            has_step_actions<detail::step_action_kind::entry> || has_step_actions<detail::step_action_kind::exit>;
        c.entered_ = c.left_ = step_set{};
        if constexpr (events_read) {
          c.activated_ = all_targets[Tr];
          c.deactivated_ = all_sources[Tr];
        }
        c.template scan_codesys_entered<N, Tr>(pou, elapsed);
        if constexpr (events_read) c.activated_ = c.deactivated_ = step_set{};
      }
    }
    template <std::size_t M, std::size_t... J>
    static constexpr void put_entries(std::array<scan_function, codesys_functions>& table, std::index_sequence<J...>) {
      ((table[entry_base + entry_offsets[M] + J] = &entered<M, J>), ...);
    }
    // The functions in the order of codesys_index.
    static constexpr auto codesys_table = [] {
      std::array<scan_function, codesys_functions> table{};
      [&]<std::size_t... M>(std::index_sequence<M...>) {
        ((table[M] = &usual<M, false>), ...);
        ((table[pending_base + M] = &usual<M, true>), ...);
        if constexpr (with_entries) {
          (put_entries<M>(table, std::make_index_sequence<candidates_in<M>.size>{}), ...);
        }
      }(std::make_index_sequence<state_count>{});
      table[no_state] = &general;
      table[changed_index] = &changed;
      table[held_index] = &held;
      return table;
    }();
  };

  // A scan with a flag set or something held (rare, so apart: the usual scan inlines the less).
  [[gnu::noinline, gnu::cold]] void scan_with_flags(POU& pou, TIME now) {
    const TIME elapsed = started() ? TIME(now - last_) : TIME{};
    last_ = now;
    scan_flagged(pou, elapsed);
  }
  // The flags' scan, `elapsed` since the last (0 before the first); on a compiled codesys chart
  // the next scan's function follows from what it left (index_after_general).
  void scan_flagged(POU& pou, TIME elapsed) {
    apply_flags(pou, elapsed);
    if constexpr (codesys_compiled) state_ = index_after_general();
  }
  void apply_flags(POU& pou, TIME elapsed) {
    if (!started() || SFCInit || SFCReset) {
      restart(pou);
      if (SFCInit) return;
    }
    if (SFCQuitError) {
      SFCError = FALSE;
      text(SFCErrorStep, "");
      text(SFCErrorPOU, "");
      hold(quit_held, true);
      return;
    }
    if (holds(quit_held)) {  // SFCQuitError fell: the active steps' times start again from 0
      hold(quit_held, false);
      restart_active_times(pou);
      elapsed = TIME{};
    }
    if (SFCPause) return;
    const bool tip = SFCTip && !holds(tip_held);
    hold(tip_held, SFCTip);
    detail::engine_access::ref(SFCTrans) = FALSE;
    scan(pou, elapsed, tip);
  }
  // A scan with no SFC flag set and nothing held (the usual one).
  void scan_usual(POU& pou, TIME elapsed) {
    if constexpr (compiled) {
      scan_compiled(pou, elapsed);
    } else {
      scan(pou, elapsed, false);
    }
  }
  // A scan after the flags were applied (SFCTip's rising edge: `tip`).
  void scan(POU& pou, TIME elapsed, bool tip) {
    if constexpr (compiled) {
      scan_compiled_flagged(pou, elapsed, tip);
    } else if constexpr (order::actions_first) {
      scan_codesys(pou, elapsed, tip);
    } else {
      scan_matiec(pou, elapsed, tip);
    }
  }

  // codesys: the state after a scan in which several transitions fired (rare, so apart): the
  // steps active now are those whose _X says so (a step one transition entered and a later one
  // left is not).
  [[gnu::noinline, gnu::cold]] std::uint8_t state_after_several(POU& pou) const {
    step_set now = active_;
    for (std::size_t w = 0; w < now.size(); ++w) {
      for (std::uint64_t m = activated_[w] | deactivated_[w]; m != 0; m &= m - 1) {
        const std::size_t i = w * 64 + static_cast<std::size_t>(std::countr_zero(m));
        if ((pou.*members[i]).X_next()) {
          detail::set_bit<step_count>(now, i);
        } else {
          detail::clear_bit<step_count>(now, i);
        }
      }
    }
    return state_of(now);
  }

  void scan_compiled(POU& pou, TIME elapsed) {
    if constexpr (order::actions_first) {
      state_functions<>::codesys_table[state_](*this, pou, elapsed);
    } else {
      take_step_events();
      state_functions<>::matiec_scans[state_](*this, pou, elapsed);
    }
  }
  // codesys, after a general scan: the state its firings lead to is found at the next change,
  // from the steps.
  void forget_next_state() noexcept { next_state_ = no_state; }
  // codesys, after a general or a flags' scan: the next scan's function (codesys_index), from
  // what the scan left (rare, so apart).
  [[gnu::noinline, gnu::cold]] std::uint8_t index_after_general() const {
    if (held_ != 0) return held_index;
    if (detail::any<step_count>(entered_) || detail::any<step_count>(left_)) return changed_index;
    const std::uint8_t m = state_of(active_);
    if (m == no_state) return no_state;
    return controls_left() ? static_cast<std::uint8_t>(pending_base + m) : m;
  }
  // A compiled chart's scan with a flag set (the tip mode, SFCTip, after SFCReset, SFCQuitError
  // or SFCPause): the general engine's, which the state follows (rare, so apart).
  [[gnu::noinline, gnu::cold]] void scan_compiled_flagged(POU& pou, TIME elapsed, bool tip) {
    if constexpr (order::actions_first) {
      scan_codesys(pou, elapsed, tip);
      activated_ = deactivated_ = step_set{};  // (empty between scans)
      forget_next_state();                     // (state_: scan_flagged)
    } else {
      scan_matiec(pou, elapsed, tip);
      state_ = state_of(active_);
    }
  }

  // --- The scan ---------------------------------------------------------------------------
  // A scan starts: the steps the last scan's transitions entered and left are this scan's
  // activations and deactivations (codesys; in the matiec order they took effect in that scan,
  // and only a reset leaves an activation pending). Whether a step changed.
  bool take_step_events() noexcept {
    activated_ = entered_;
    if constexpr (order::actions_first) {
      deactivated_ = left_;
    } else {
      deactivated_ = step_set{};
    }
    entered_ = left_ = step_set{};
    return detail::any<step_count>(activated_) || detail::any<step_count>(deactivated_);
  }

  void scan_codesys(POU& pou, TIME elapsed, bool tip) {
    take_step_events();
    scan_codesys_rest(pou, elapsed, tip);
  }

  void scan_codesys_rest(POU& pou, TIME elapsed, bool tip) {
    if (detail::any<step_count>(activated_) || detail::any<step_count>(deactivated_)) {
      step_set changed = activated_;
      for (std::size_t w = 0; w < changed.size(); ++w) changed[w] |= deactivated_[w];
      detail::for_each_bit<step_count>(changed, apply_pending_table, *this, pou, elapsed);
      current_step();  // the steps the last cycle's transitions activated are active now
    }
    if (detail::any<step_count>(activated_) || detail::any<step_count>(deactivated_) || has_active_actions) {
      detail::for_each_bit<step_count>(active_, advance_time_table, *this, pou, elapsed);
      steps_of_scan(pou, elapsed);
    } else {  // no step changed and no step action: one pass over the active steps
      detail::for_each_bit<step_count>(active_, advance_and_check_table, *this, pou, elapsed);
    }
    iec_actions(pou, elapsed);
    fire(pou, tip);
  }

  void scan_matiec(POU& pou, TIME elapsed, bool tip) {
    take_step_events();
    scan_matiec_rest(pou, elapsed, tip);
  }

  void scan_matiec_rest(POU& pou, TIME elapsed, bool tip) {
    detail::for_each_bit<step_count>(active_, advance_time_table, *this, pou, elapsed);
    fire(pou, tip);
    if (SFCTrans) apply_matiec_evolution(pou, elapsed);
    steps_of_scan(pou, elapsed);
    iec_actions(pou, elapsed);
  }

  // matiec: the transitions of this scan take effect now.
  void apply_matiec_evolution(POU& pou, TIME elapsed) {
    detail::for_each_bit<step_count>(left_, apply_left_table, *this, pou, elapsed);
    detail::for_each_bit<step_count>(entered_, apply_entered_table, *this, pou, elapsed);
    for (std::size_t w = 0; w < active_.size(); ++w) {
      active_[w] = (active_[w] & ~left_[w]) | entered_[w];
      activated_[w] |= entered_[w];
      deactivated_[w] = left_[w];
    }
    entered_ = left_ = step_set{};
    current_step();
  }

  step_set active_{};       // the steps whose X is TRUE
  step_set entered_{};      // activated by this scan's transitions (codesys: for the next cycle)
  step_set left_{};         // left by this scan's transitions
  step_set activated_{};    // activated: this scan's actions see it
  step_set deactivated_{};  // deactivated: this scan's actions see it
  action_set q_{};          // the actions whose Q is TRUE
  action_set final_{};      // the actions whose final scan is this scan
  action_set pulsed_{};     // recomputed next scan: a pulse ends, or A falls after a final scan
  action_set timing_{};     // recomputed every scan while an SD delay or SL limit runs
  action_set dirty_{};      // to recompute in this scan
  std::array<detail::control, action_count> controls_{};
  std::array<action_state, action_count> states_{};
  TIME last_{};
  // Compiled engine: matiec, the state of the active steps (no_state: the general scan); codesys,
  // the index of the next scan's function (codesys_index; first, the held one: not started).
  std::uint8_t state_ = codesys_compiled ? held_index : 0;
  std::uint8_t next_state_ = 0;  // ... the state the scan's transitions lead to (codesys: for the next scan)
  // What makes a scan other than the usual, besides the flags: not yet started (the first scan
  // starts the chart), SFCQuitError's hold, SFCTip's value in the last scan (its rising edge).
  static constexpr std::uint8_t not_started = 1, quit_held = 2, tip_held = 4;
  std::uint8_t held_ = not_started;
  [[nodiscard]] bool holds(std::uint8_t what) const noexcept { return (held_ & what) != 0; }
  void hold(std::uint8_t what, bool on) noexcept {
    held_ = static_cast<std::uint8_t>(on ? held_ | what : held_ & ~what);
  }
  [[nodiscard]] bool started() const noexcept { return !holds(not_started); }
};

}  // namespace iecoop::sfc

#include <iecoop/detail/pop_macros.hpp>
