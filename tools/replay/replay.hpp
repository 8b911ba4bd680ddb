// iecoop-replay's reading and replaying of a stimulus (see iecoop_replay.cpp for the tool and
// the stimulus format), in a header of its own so that the fuzz target tests/fuzz/replay_csv.cpp
// runs the same code as the tool.
#pragma once

#include <iecoop/iecoop.hpp>

#include <charconv>
#include <cstddef>
#include <cstdint>
#include <iterator>
#include <limits>
#include <optional>
#include <sstream>
#include <string>
#include <string_view>
#include <type_traits>
#include <utility>
#include <vector>

namespace iecoop_replay {

using namespace iecoop;

/// Bad input: the message, already naming where.
struct input_error {
  std::string message;
};

// --- CSV ------------------------------------------------------------------------------

/// The fields of one CSV line, each as written (quotes kept, so extra columns are copied
/// through unchanged). A quoted field may hold commas and doubled quotes, not line breaks.
inline std::optional<std::vector<std::string>> split_fields(std::string_view line) {
  std::vector<std::string> fields;
  std::size_t i = 0;
  while (true) {
    const std::size_t start = i;
    if (i < line.size() && line[i] == '"') {
      ++i;
      while (true) {
        if (i >= line.size()) return std::nullopt;  // unterminated quote
        if (line[i] == '"') {
          if (i + 1 < line.size() && line[i + 1] == '"') {
            i += 2;
            continue;
          }
          ++i;
          break;
        }
        ++i;
      }
      if (i < line.size() && line[i] != ',') return std::nullopt;  // text after the closing quote
    } else {
      while (i < line.size() && line[i] != ',') ++i;
    }
    fields.emplace_back(line.substr(start, i - start));
    if (i >= line.size()) break;
    ++i;  // the comma
  }
  return fields;
}

// --- Values -----------------------------------------------------------------------------

/// A whole non-negative decimal number (digits only) no larger than `max`.
inline std::optional<std::uint64_t> parse_unsigned(std::string_view text, std::uint64_t max) {
  if (text.empty()) return std::nullopt;
  for (const char c : text) {
    if (c < '0' || c > '9') return std::nullopt;
  }
  std::uint64_t value = 0;
  const auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), value);
  if (ec != std::errc() || end != text.data() + text.size() || value > max) return std::nullopt;
  return value;
}

/// The largest time_ms whose nanoseconds fit the cycle clock's LTIME.
constexpr std::uint64_t max_time_ms = std::numeric_limits<std::uint64_t>::max() / 1'000'000;

/// Parses a pin's value written in the stimulus; on failure returns why.
template <class T>
std::optional<std::string> parse_pin_value(std::string_view text, T& value) {
  if constexpr (std::is_same_v<T, BOOL>) {
    if (text == "0" || text == "1") {
      value = BOOL(text == "1");
      return std::nullopt;
    }
    return "a BOOL is 0 or 1";
  } else if constexpr (std::is_same_v<T, TIME>) {
    if (const auto ms = parse_unsigned(text, std::numeric_limits<TIME::rep>::max())) {
      value = TIME::from_ticks(static_cast<TIME::rep>(*ms));
      return std::nullopt;
    }
    return "a TIME is a whole number of milliseconds from 0 to 4294967295";
  } else {
    static_assert(AnyInteger<T>, "iecoop-replay: a pin type without a stimulus encoding");
    using rep = typename T::rep;
    const bool negative = !text.empty() && text.front() == '-';
    const std::string_view digits = text.substr(negative || (!text.empty() && text.front() == '+') ? 1 : 0);
    const auto magnitude = parse_unsigned(digits, std::numeric_limits<std::uint64_t>::max());
    std::ostringstream why;
    why << "an " << (std::is_signed_v<rep> ? "INT" : "unsigned integer") << " here is a decimal number from "
        << +std::numeric_limits<rep>::min() << " to " << +std::numeric_limits<rep>::max();
    if (!magnitude) return why.str();
    if (negative) {
      if (*magnitude > 0 &&
          !(std::is_signed_v<rep> && *magnitude <= static_cast<std::uint64_t>(std::numeric_limits<rep>::max()) + 1u)) {
        return why.str();
      }
      value = T(static_cast<rep>(-static_cast<std::int64_t>(*magnitude)));
    } else {
      if (!std::in_range<rep>(*magnitude)) return why.str();
      value = T(static_cast<rep>(*magnitude));
    }
    return std::nullopt;
  }
}

/// An output's value in the trace's encoding.
template <class T>
std::string format_pin_value(const T& value) {
  if constexpr (std::is_same_v<T, BOOL>) {
    return value ? "1" : "0";
  } else if constexpr (std::is_same_v<T, TIME>) {
    return std::to_string(value.count());
  } else {
    return std::to_string(+value.value());
  }
}

// --- Pins -------------------------------------------------------------------------------

/// The type of the variable a pin member designates (outputs are read_only<T, ...>).
template <class T>
struct pin_value {
  using type = T;
};
template <class T>
  requires iecoop::detail::value_wrapper<T>
struct pin_value<T> {
  using type = iecoop::detail::unwrapped_t<const T&>;
};
template <class M>
struct member_type;
template <class T, class C>
struct member_type<T C::*> {
  using type = T;
};
template <auto Member>
using pin_value_t = typename pin_value<typename member_type<std::remove_cv_t<decltype(Member)>>::type>::type;

/// The column name of a pin: its formal name, with `_ms` for a TIME.
template <auto Member>
std::string column_name() {
  std::string name(member_name<Member>);
  if constexpr (std::is_same_v<pin_value_t<Member>, TIME>) name += "_ms";
  return name;
}

/// The other spelling a column of this pin may have: CODESYS's RESET and LOAD for IEC's R
/// and LD of the counters, and the other way round.
inline std::string_view alternative_name(std::string_view name, bool is_counter) {
  if (!is_counter) return {};
  if (name == "R") return "RESET";
  if (name == "RESET") return "R";
  if (name == "LD") return "LOAD";
  if (name == "LOAD") return "LD";
  return {};
}

/// How to read one input of block B from a stimulus field.
template <class B>
struct input_pin {
  std::string column;
  std::string_view alternative;
  std::optional<std::string> (*assign)(B&, std::string_view);
};

/// How to write one output of block B.
template <class B>
struct output_pin {
  std::string column;
  std::string (*read)(const B&);
};

template <class B, std::size_t... I>
std::vector<input_pin<B>> input_pins(bool is_counter, std::index_sequence<I...>) {
  using pins = inputs_of<B>;
  return {input_pin<B>{column_name<pin<pins, I>>(), alternative_name(pins::names[I], is_counter),
                       [](B& block, std::string_view text) { return parse_pin_value(text, block.*pin<pins, I>); }}...};
}

template <class B, std::size_t... I>
std::vector<output_pin<B>> output_pins(std::index_sequence<I...>) {
  using pins = outputs_of<B>;
  return {output_pin<B>{column_name<pin<pins, I>>(), [](const B& block) {
                          return format_pin_value(pin_value_t<pin<pins, I>>((block.*pin<pins, I>).get()));
                        }}...};
}

// --- The replay -------------------------------------------------------------------------

inline std::string where(std::size_t line, std::string_view column) {
  std::ostringstream text;
  text << "row " << line - 1 << " (line " << line << ")";
  if (!column.empty()) text << ", column \"" << column << "\"";
  return text.str();
}

/// A column's name without `prefix` and a dot in front: with the prefix `IO_PRG.tJam`, the
/// column `IO_PRG.tJam.IN` of a recorded trace is the input IN. Without a prefix, the name.
inline std::string_view unprefixed(std::string_view name, std::string_view prefix) {
  if (prefix.empty() || name.size() <= prefix.size() + 1 || !name.starts_with(prefix) || name[prefix.size()] != '.') {
    return prefix.empty() ? name : std::string_view{};
  }
  return name.substr(prefix.size() + 1);
}

/// Replays `stimulus` on a fresh block B (its `inputs` set from the columns of their names,
/// its `outputs` written after them); returns the trace, or throws input_error. With a
/// `prefix`, the inputs are the columns named `<prefix>.<input>` (a trace recorded with
/// iecoop's trace recorder names a block's pins so) and every other column is copied through.
template <class B>
std::string replay_with(std::string_view stimulus, std::string_view fb_name, const std::vector<input_pin<B>>& inputs,
                        const std::vector<output_pin<B>>& outputs, std::string_view prefix = {}) {
  // A UTF-8 byte order mark (spreadsheets write one) is no part of the header.
  if (stimulus.starts_with("\xEF\xBB\xBF")) stimulus.remove_prefix(3);
  // Lines, without their line breaks (LF, CRLF, or a CR alone); a last line break ends the file.
  std::vector<std::string_view> lines;
  for (std::size_t start = 0; start < stimulus.size();) {
    std::size_t end = stimulus.find_first_of("\r\n", start);
    if (end == std::string_view::npos) end = stimulus.size();
    lines.push_back(stimulus.substr(start, end - start));
    start = end + 1;
    if (end < stimulus.size() && stimulus[end] == '\r' && start < stimulus.size() && stimulus[start] == '\n') ++start;
  }
  if (lines.empty()) throw input_error{"line 1: the stimulus is empty; it needs the header cycle,time_ms,<inputs...>"};

  // The header.
  const auto header = split_fields(lines[0]);
  if (!header) throw input_error{"line 1 (header): a quoted column name is not closed"};
  if (header->size() < 2 || (*header)[0] != "cycle" || (*header)[1] != "time_ms") {
    throw input_error{"line 1 (header): the first two columns must be cycle,time_ms"};
  }
  std::vector<std::ptrdiff_t> column_input(header->size(), -1);  // which input each column sets
  std::vector<bool> seen(inputs.size(), false);
  for (std::size_t c = 2; c < header->size(); ++c) {
    const std::string_view name = unprefixed((*header)[c], prefix);
    for (std::size_t i = 0; i < inputs.size(); ++i) {
      if (name == inputs[i].column || (!inputs[i].alternative.empty() && name == inputs[i].alternative)) {
        if (seen[i])
          throw input_error{"line 1 (header), column \"" + (*header)[c] + "\": input " + inputs[i].column +
                            " is given twice"};
        seen[i] = true;
        column_input[c] = static_cast<std::ptrdiff_t>(i);
      }
    }
    if ((*header)[c] == "cycle" || (*header)[c] == "time_ms")
      throw input_error{"line 1 (header), column \"" + (*header)[c] + "\": given twice"};
  }
  for (std::size_t i = 0; i < inputs.size(); ++i) {
    if (!seen[i]) {
      const std::string column = prefix.empty() ? inputs[i].column : std::string(prefix) + "." + inputs[i].column;
      throw input_error{"line 1 (header), column \"" + column + "\": missing; " + std::string(fb_name) +
                        " needs a column for each of its inputs"};
    }
  }

  // The trace's header: cycle, time, the inputs as given, the outputs, the extra columns.
  std::string trace = "cycle,time_ms";
  for (std::size_t c = 2; c < header->size(); ++c) {
    if (column_input[c] >= 0) {
      trace += ',';
      trace += (*header)[c];
    }
  }
  for (const output_pin<B>& output : outputs) {
    trace += ',';
    trace += output.column;
  }
  for (std::size_t c = 2; c < header->size(); ++c) {
    if (column_input[c] < 0) {
      trace += ',';
      trace += (*header)[c];
    }
  }
  trace += '\n';

  // The rows: one call each, on one instance.
  B block;
  std::uint64_t previous_ms = 0;
  std::size_t last = lines.size();
  while (last > 1 && lines[last - 1].empty()) --last;  // blank lines at the end
  for (std::size_t l = 1; l < last; ++l) {
    const std::size_t line_number = l + 1;
    const auto fields = split_fields(lines[l]);
    if (!fields)
      throw input_error{where(line_number, "") + ": a quoted field is not closed, or text follows its closing quote"};
    if (fields->size() != header->size()) {
      throw input_error{where(line_number, "") + ": " + std::to_string(fields->size()) +
                        " fields, but the header has " + std::to_string(header->size())};
    }
    if (!parse_unsigned((*fields)[0], std::numeric_limits<std::uint64_t>::max())) {
      throw input_error{where(line_number, "cycle") + ": \"" + (*fields)[0] + "\" is not a whole number"};
    }
    const auto time_ms = parse_unsigned((*fields)[1], max_time_ms);
    if (!time_ms) {
      throw input_error{where(line_number, "time_ms") + ": \"" + (*fields)[1] +
                        "\" is not a whole number of milliseconds from 0 to " + std::to_string(max_time_ms)};
    }
    if (l > 1 && *time_ms < previous_ms) {
      throw input_error{where(line_number, "time_ms") + ": time goes backwards, from " + std::to_string(previous_ms) +
                        " to " + std::to_string(*time_ms) + " ms"};
    }
    previous_ms = *time_ms;

    cycle_clock::set(LTIME::from_ticks(*time_ms * 1'000'000));
    for (std::size_t c = 2; c < header->size(); ++c) {
      if (column_input[c] < 0) continue;
      if (const auto why = inputs[static_cast<std::size_t>(column_input[c])].assign(block, (*fields)[c])) {
        throw input_error{where(line_number, (*header)[c]) + ": \"" + (*fields)[c] + "\" is not valid; " + *why};
      }
    }
    block();

    // Appends, not `a + "," + b`: GCC 12 -O3 warns of a false overlap in operator+ (-Wrestrict).
    trace += (*fields)[0];
    trace += ',';
    trace += (*fields)[1];
    for (std::size_t c = 2; c < header->size(); ++c) {
      if (column_input[c] >= 0) {
        trace += ',';
        trace += (*fields)[c];
      }
    }
    for (const output_pin<B>& output : outputs) {
      trace += ',';
      trace += output.read(block);
    }
    for (std::size_t c = 2; c < header->size(); ++c) {
      if (column_input[c] < 0) {
        trace += ',';
        trace += (*fields)[c];
      }
    }
    trace += '\n';
  }
  return trace;
}

/// replay_with() on block B's VAR_INPUTs and VAR_OUTPUTs.
template <class B>
std::string replay(std::string_view stimulus, std::string_view fb_name, bool is_counter, std::string_view prefix = {}) {
  return replay_with<B>(stimulus, fb_name, input_pins<B>(is_counter, std::make_index_sequence<inputs_of<B>::size>{}),
                        output_pins<B>(std::make_index_sequence<outputs_of<B>::size>{}), prefix);
}

/// The blocks the tool drives, in dialect D.
/// Replays `stimulus` on the block called `fb` in dialect D; nothing if there is no such
/// block. With check_name_only, only says whether there is one (an empty trace).
template <Dialect D>
std::optional<std::string> replay_in(std::string_view fb, std::string_view stimulus, bool check_name_only = false,
                                     std::string_view prefix = {}) {
  const auto run = [&]<class B>(bool is_counter) -> std::optional<std::string> {
    if (check_name_only) return std::string();
    return replay<B>(stimulus, fb, is_counter, prefix);
  };
  if (fb == "TON") return run.template operator()<TON>(false);
  if (fb == "TOF") return run.template operator()<TOF>(false);
  if (fb == "TP") return run.template operator()<TP>(false);
  if (fb == "CTU") return run.template operator()<up_counter<INT, D>>(true);
  if (fb == "CTD") return run.template operator()<down_counter<INT, D>>(true);
  if (fb == "CTUD") return run.template operator()<up_down_counter<INT, D>>(true);
  if (fb == "R_TRIG") return run.template operator()<R_TRIG>(false);
  if (fb == "F_TRIG") return run.template operator()<falling_edge_trigger<D>>(false);
  if (fb == "SR") return run.template operator()<SR>(false);
  if (fb == "RS") return run.template operator()<RS>(false);
  return std::nullopt;
}

/// The message with every control character shown as \xNN: a field's invisible bytes (a tab,
/// an escape sequence) appear in the error instead of acting on the terminal.
inline std::string visible(std::string_view message) {
  std::string result;
  for (const char c : message) {
    const auto byte = static_cast<unsigned char>(c);
    if (byte < 0x20 || byte == 0x7F) {
      constexpr std::string_view hex = "0123456789ABCDEF";
      result += "\\x";
      result += hex[byte >> 4];
      result += hex[byte & 0xF];
    } else {
      result += c;
    }
  }
  return result;
}

}  // namespace iecoop_replay
