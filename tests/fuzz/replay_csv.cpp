// Fuzz target: iecoop-replay's stimulus reader (tools/replay/replay.hpp, the code the tool runs).
// Every input is replayed on each block the tool drives, in each dialect where the block differs.
// Checks, for any input:
//   - it is a trace or an input_error, whose message names where (line 1, or row and line) and,
//     as the tool prints it, holds no control character;
//   - a trace is lines of the header's number of CSV fields, starting cycle,time_ms;
//   - the trace is itself a good stimulus (its outputs then copied through as extra columns),
//     whose replay gives the same outputs row by row: the block saw what the stimulus said.
#include "replay.hpp"

#include "fuzz_check.hpp"

#include <cstddef>
#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace {

using namespace iecoop;
using iecoop_fuzz::require;

std::vector<std::string_view> lines_of(std::string_view trace) {
  std::vector<std::string_view> lines;
  while (!trace.empty()) {
    const std::size_t end = trace.find('\n');
    lines.push_back(trace.substr(0, end));
    trace.remove_prefix(end + 1);
  }
  return lines;
}

template <class B>
void replay_on(std::string_view stimulus, bool is_counter) {
  std::string trace;
  try {
    trace = iecoop_replay::replay<B>(stimulus, "FB", is_counter);
  } catch (const iecoop_replay::input_error& error) {
    const std::string_view message = error.message;
    require(message.starts_with("line ") || message.starts_with("row "), "an error names where", message);
    for (const char c : iecoop_replay::visible(message)) {
      const auto byte = static_cast<unsigned char>(c);
      require(byte >= 0x20 && byte != 0x7F, "an error as printed holds no control character", message);
    }
    return;
  }
  require(trace.starts_with("cycle,time_ms") && trace.ends_with('\n'), "a trace starts with its header", trace);
  const std::vector<std::string_view> lines = lines_of(trace);
  const auto header = iecoop_replay::split_fields(lines.front());
  require(header.has_value(), "a trace's header is CSV", lines.front());
  const std::size_t columns = header->size();
  for (const std::string_view line : lines) {
    const auto fields = iecoop_replay::split_fields(line);
    require(fields.has_value() && fields->size() == columns, "each row of a trace has the header's fields", line);
  }

  // The trace as a stimulus: the same inputs, its outputs now extra columns.
  std::string again;
  try {
    again = iecoop_replay::replay<B>(trace, "FB", is_counter);
  } catch (const iecoop_replay::input_error& error) {
    require(false, "a trace is a good stimulus", error.message);
  }
  const std::vector<std::string_view> again_lines = lines_of(again);
  require(again_lines.size() == lines.size(), "a trace's replay has its rows", again);
  constexpr std::size_t first_output = 2 + inputs_of<B>::size;
  constexpr std::size_t outputs = outputs_of<B>::size;
  for (std::size_t l = 0; l < lines.size(); ++l) {
    const auto fields = iecoop_replay::split_fields(lines[l]).value_or(std::vector<std::string>{});
    const auto again_fields = iecoop_replay::split_fields(again_lines[l]).value_or(std::vector<std::string>{});
    // cycle, time, inputs, outputs, then the first trace's outputs and extra columns.
    std::vector<std::string> expected(fields.begin(), fields.begin() + first_output + outputs);
    expected.insert(expected.end(), fields.begin() + first_output, fields.end());
    require(again_fields == expected, "a trace replayed gives the same outputs", again_lines[l]);
  }
}

template <Dialect D>
void replay_counters(std::string_view stimulus) {
  replay_on<up_counter<INT, D>>(stimulus, true);
  replay_on<down_counter<INT, D>>(stimulus, true);
  replay_on<up_down_counter<INT, D>>(stimulus, true);
  replay_on<falling_edge_trigger<D>>(stimulus, false);
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string_view stimulus = iecoop_fuzz::as_text(data, size);
  replay_on<TON>(stimulus, false);
  replay_on<TOF>(stimulus, false);
  replay_on<TP>(stimulus, false);
  replay_on<R_TRIG>(stimulus, false);
  replay_on<SR>(stimulus, false);
  replay_on<RS>(stimulus, false);
  replay_counters<codesys::dialect>(stimulus);
  replay_counters<iec::dialect>(stimulus);
  replay_counters<matiec::dialect>(stimulus);
  return 0;
}
