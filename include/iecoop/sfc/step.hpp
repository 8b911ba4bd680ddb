// SPDX-License-Identifier: MIT
// iecoop/sfc/step.hpp — an SFC step as the POU's code reads it (CODESYS's SFCStepType): `FILL.X`,
// `FILL.T`, `FILL._X`; and an IEC action's control as it is read (`Q`, `A`).
//
//     sfc::step INIT, FILL;                      // the steps are members of the POU
//     if (FILL.X && FILL.T >= T#50ms) ...        // ST: IF FILL.X AND FILL.T >= T#50ms THEN
//
// Only the chart writes them (they are read_only<> variables), as only the SFC runtime writes
// the implicit variables of a CODESYS chart.
#pragma once

#include <cstddef>
#include <string_view>

#include <iecoop/config.hpp>
#include <iecoop/pou/variables.hpp>
#include <iecoop/types/elementary.hpp>
#include <iecoop/types/string.hpp>
#include <iecoop/types/time.hpp>

#include <iecoop/detail/push_macros.hpp>

namespace iecoop::sfc {

namespace detail {
/// The one writer of steps and action states: the chart's engine.
struct engine_access;
}  // namespace detail

/**
 * A step of an SFC chart: declare one member per step in the POU (`sfc::step FILL;`) and name
 * it in the chart (`sfc::STEP<&P::FILL, ...>`).
 *
 * - `X`: the step is active in this cycle (IEC, CODESYS `x`).
 * - `T`: the time since the step's last activation; it keeps its value once the step is left
 *   (IEC), and restarts at T#0ms when the step is activated again, also by a self-loop.
 * - `_X`: the step is active in the next cycle (CODESYS `_x`). In the matiec scan order, where a
 *   step becomes active in the scan that activates it, `_X` equals `X` after each scan.
 *   (An identifier that begins with `_` and a capital is reserved to the C++ implementation;
 *   iecoop declares it because CODESYS names the flag so, and it is safe on GCC and Clang. A C
 *   library that defines `_X` as a macro — newlib's <ctype.h> — hides it; read `X_next` there.)
 */
class step {
 public:
  read_only<BOOL, detail::engine_access> X;
  read_only<TIME, detail::engine_access> T;
#pragma push_macro("_X")
#undef _X
  read_only<BOOL, detail::engine_access> _X;
  /// `_X` under a name no C library takes.
  [[nodiscard]] constexpr BOOL X_next() const noexcept { return _X; }
#pragma pop_macro("_X")
};

/**
 * The control of an IEC action as the POU reads it: `chart.action<&P::A_FILL>().Q`.
 *
 * - `Q`: the action is active in this scan (IEC ACTION_CONTROL's Q; CODESYS `_A_FILL._x`).
 * - `A`: the action's body runs in this scan (IEC edition 3's A; CODESYS `_A_FILL.x`): Q, and in
 *   the codesys scan order also the one final scan after Q falls.
 */
struct action_state {
  read_only<BOOL, detail::engine_access> Q;
  read_only<BOOL, detail::engine_access> A;
};

/**
 * A step's name as the chart's SFCCurrentStep gives it: read like a STRING (`STRING<> s =
 * chart.SFCCurrentStep;`, `chart.SFCCurrentStep == 'FILL'`), kept as a view of the name, so the
 * chart copies no text when its steps change.
 */
class step_name_view {
 public:
  /// The name as a STRING.
  [[nodiscard]] constexpr STRING<> get() const noexcept { return STRING<>(name_); }
  constexpr operator STRING<>() const noexcept { return get(); }  // NOLINT: reads as a STRING
  /// The name itself.
  [[nodiscard]] constexpr std::string_view view() const noexcept { return name_; }

  friend constexpr BOOL operator==(const step_name_view& a, std::string_view b) noexcept { return BOOL(a.name_ == b); }
  template <std::size_t N>
  friend constexpr BOOL operator==(const step_name_view& a, const STRING<N>& b) noexcept {
    return BOOL(a.name_ == b.view());
  }

 private:
  friend struct detail::engine_access;
  std::string_view name_;
};

}  // namespace iecoop::sfc

#include <iecoop/detail/pop_macros.hpp>
