// iecoop-replay's SFC charts: the eight reference charts of examples/sfc, each with the columns
// its trace has (tests/replay/sfc/<chart>.columns): the inputs, then for each step
// <step>_X and <step>_T_ms, then the program's other variables (a TIME as <name>_ms).
#pragma once

#include "replay.hpp"

#include <SFC_ALT.hpp>
#include <SFC_FIRST_SCAN.hpp>
#include <SFC_LINEAR.hpp>
#include <SFC_PAR.hpp>
#include <SFC_QUAL.hpp>
#include <SFC_SHARED.hpp>
#include <SFC_TIMED.hpp>

#include <cstddef>
#include <optional>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

namespace iecoop_replay {

/// The charts the tool replays, as named on its command line.
inline constexpr std::string_view chart_names =
    "SFC_ALT SFC_ALT_PRIO SFC_FIRST_SCAN SFC_LINEAR SFC_PAR SFC_QUAL SFC_SHARED SFC_TIMED";

/// A program's variable as a trace column.
template <class B, auto Member>
output_pin<B> variable_column() {
  return output_pin<B>{column_name<Member>(),
                       [](const B& program) { return format_pin_value(pin_value_t<Member>(program.*Member)); }};
}

/// A program's variable as an input column of the stimulus.
template <class B, auto Member>
input_pin<B> input_column() {
  return input_pin<B>{column_name<Member>(), {}, [](B& program, std::string_view text) {
                        return parse_pin_value(text, program.*Member);
                      }};
}

/// For each step of B's chart, in declaration order: <step>_X, <step>_T_ms.
template <class B, std::size_t... I>
std::vector<output_pin<B>> step_columns(std::index_sequence<I...>) {
  constexpr auto names = decltype(B::chart)::step_names();
  std::vector<output_pin<B>> columns;
  (
      [&] {
        constexpr auto member = decltype(B::chart)::step_members()[I];
        columns.push_back(output_pin<B>{std::string(names[I]) + "_X",
                                        [](const B& program) { return format_pin_value(BOOL((program.*member).X)); }});
        columns.push_back(output_pin<B>{std::string(names[I]) + "_T_ms",
                                        [](const B& program) { return format_pin_value(TIME((program.*member).T)); }});
      }(),
      ...);
  return columns;
}

/// Replays a chart B whose inputs are Inputs and whose other variables are Variables.
template <class B, auto... Inputs>
struct chart_replay {
  template <auto... Variables>
  static std::string run(std::string_view stimulus, std::string_view name) {
    std::vector<output_pin<B>> outputs =
        step_columns<B>(std::make_index_sequence<decltype(B::chart)::step_names().size()>{});
    (outputs.push_back(variable_column<B, Variables>()), ...);
    return replay_with<B>(stimulus, name, {input_column<B, Inputs>()...}, outputs);
  }
};

/// Replays `stimulus` on the chart called `name` in scan order O; nothing if there is no such
/// chart. With check_name_only, only says whether there is one (an empty trace).
template <iecoop::sfc::ScanOrder O>
std::optional<std::string> replay_chart(std::string_view name, std::string_view stimulus,
                                        bool check_name_only = false) {
  using namespace sfc_reference;
  if (name == "SFC_ALT" || name == "SFC_ALT_PRIO") {
    if (check_name_only) return std::string();
    const auto run = [&]<class B>() {
      return chart_replay<B, &B::GO_A, &B::GO_B, &B::DONE, &B::ABORT>::template run<&B::C_INIT, &B::C_A, &B::C_B,
                                                                                    &B::C_JOIN>(stimulus, name);
    };
    return name == "SFC_ALT" ? run.template operator()<P_SFC_ALT<O>>() : run.template operator()<P_SFC_ALT_PRIO<O>>();
  }
  if (name == "SFC_FIRST_SCAN") {
    if (check_name_only) return std::string();
    using B = P_SFC_FIRST_SCAN<O>;
    return chart_replay<B, &B::GO, &B::BACK, &B::AGAIN>::template run<&B::C_INIT_N, &B::C_INIT_P, &B::C_INIT_P0,
                                                                      &B::C_S1>(stimulus, name);
  }
  if (name == "SFC_LINEAR") {
    if (check_name_only) return std::string();
    using B = P_SFC_LINEAR<O>;
    return chart_replay<B, &B::START>::template run<&B::C_INIT, &B::C_FILL, &B::C_PULSE, &B::C_HEAT, &B::FILL_T_SEEN,
                                                    &B::K>(stimulus, name);
  }
  if (name == "SFC_PAR") {
    if (check_name_only) return std::string();
    using B = P_SFC_PAR<O>;
    return chart_replay<B, &B::GO, &B::IN_Q, &B::IN_J>::template run<&B::C_INIT, &B::C_P1, &B::C_P2, &B::C_Q1, &B::C_Q2,
                                                                     &B::C_JOIN>(stimulus, name);
  }
  if (name == "SFC_QUAL") {
    if (check_name_only) return std::string();
    using B = P_SFC_QUAL<O>;
    return chart_replay<B, &B::NEXT>::template run<&B::C_N, &B::C_S, &B::C_P, &B::C_P1, &B::C_P0, &B::V_N, &B::V_S,
                                                   &B::V_P>(stimulus, name);
  }
  if (name == "SFC_SHARED") {
    if (check_name_only) return std::string();
    using B = P_SFC_SHARED<O>;
    return chart_replay<B, &B::NEXT, &B::BACK>::template run<&B::C_SH, &B::C_Q>(stimulus, name);
  }
  if (name == "SFC_TIMED") {
    if (check_name_only) return std::string();
    using B = P_SFC_TIMED<O>;
    return chart_replay<B, &B::NEXT>::template run<&B::C_L, &B::C_D, &B::C_SD, &B::C_DS, &B::C_SL, &B::V_L, &B::V_D>(
        stimulus, name);
  }
  return std::nullopt;
}

}  // namespace iecoop_replay
