// SPDX-License-Identifier: MIT
// iecoop/testing/diagram.hpp — timing-diagram expectations: the expected course of signals,
// cycle by cycle, as a picture (BOOL: `_` FALSE, `#` TRUE, `.` any) or a table of values
// separated by spaces (`0 0 1 1 2`, `T#0ms T#10ms`, `.` any). Driven lanes are written before
// each cycle; expected lanes are recorded after it by a trace recorder and compared.
//
//     TON tmr;  tmr.PT = "T#20ms"_iec;
//     testing::cycles run{tmr, "T#10ms"_iec};
//     CHECK(testing::run_diagram(run,
//         testing::drive("IN", tmr.IN,  "__####____"),
//         testing::expect("Q", tmr.Q,   "____##____"),
//         testing::expect("ET", tmr.ET, "0 0 0 10 20 20 0 0 0 0")));   // TIME: ms or T#...
//
// On failure the check prints the lanes aligned, expected above actual, and marks the first
// cycle where they differ:
//
//     timing diagram: Q differs from cycle 4 (T#40ms)
//     cycle     0123456789
//     IN        __####____
//     Q  expect ____##____
//        actual _____#____
//                   ^
//
// run_table() does the same from a CSV table in iecoop-replay's format (`cycle,time_ms,IN,
// PT_ms,Q,ET_ms,note`: BOOL 0/1, TIME in ms with the column named NAME_ms): per row the time
// is set to time_ms, the driven columns are written, one cycle runs, the expected columns are
// compared; a failure names the first differing line, its note, and expected against actual.
// IWYU pragma: private, include <iecoop/testing.hpp>
#pragma once

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <memory>
#include <optional>
#include <ostream>
#include <string>
#include <string_view>
#include <type_traits>
#include <vector>

#include <iecoop/testing/driver.hpp>
#include <iecoop/testing/forcing.hpp>
#include <iecoop/trace.hpp>
#include <iecoop/types/date_time_text.hpp>
#include <iecoop/types/enumeration.hpp>
#include <iecoop/types/literal_text.hpp>

#include <iecoop/detail/push_macros.hpp>

namespace iecoop::testing {

namespace detail {

/// A token of a lane or a table cell as a value of T, if it is one.
template <class T>
std::optional<T> parse_token(std::string_view token) {
  if constexpr (std::is_same_v<T, BOOL>) {
    if (token == "1" || token == "#" || iecoop::detail::iequals(token, "TRUE")) return TRUE;
    if (token == "0" || token == "_" || iecoop::detail::iequals(token, "FALSE")) return FALSE;
    return std::nullopt;
  } else if constexpr (Enumeration<T>) {
    const auto r = parse_enum<T>(token);
    return r ? std::optional<T>(r.value_or(T{})) : std::nullopt;
  } else if constexpr (AnyInteger<T>) {
    const auto r = parse_integer<T>(token);
    return r ? std::optional<T>(r.value_or(T{})) : std::nullopt;
  } else if constexpr (AnyReal<T>) {
    const auto r = parse_real<T>(token);
    return r ? std::optional<T>(r.value_or(T{})) : std::nullopt;
  } else if constexpr (std::is_same_v<T, TIME> || std::is_same_v<T, LTIME>) {
    // A bare number is milliseconds, as in the replay format.
    if (const parse_result<LINT> ms = parse_integer<LINT>(token)) {
      return T(LTIME(TIME::from_ticks(static_cast<TIME::rep>(ms.value_or(LINT{}).value()))));
    }
    if constexpr (std::is_same_v<T, TIME>) {
      const parse_result<TIME> r = parse_time(token);
      return r ? std::optional<T>(r.value_or(T{})) : std::nullopt;
    } else {
      const parse_result<LTIME> r = parse_ltime(token);
      return r ? std::optional<T>(r.value_or(T{})) : std::nullopt;
    }
  } else if constexpr (AnyDate<T>) {
    const auto r = parse_time_point<T>(token);
    return r ? std::optional<T>(r.value_or(T{})) : std::nullopt;
  } else {
    static_assert(sizeof(T) == 0,
                  "iecoop: a timing diagram's lane is BOOL, an integer, a bit string, REAL, TIME or a date");
    return std::nullopt;
  }
}

template <class T>
std::string text_of(const T& value) {
  char out[64];
  const char* end = to_text(out, value);
  return std::string(out, static_cast<std::size_t>(end - out));
}

/// The cells of a lane: a picture (one character per cycle) or tokens separated by spaces.
inline std::vector<std::string> cells_of(std::string_view text, bool picture_allowed) {
  std::vector<std::string> cells;
  const bool tokens = !picture_allowed || text.find_first_of(" \t|") != std::string_view::npos;
  if (!tokens) {
    for (const char c : text) cells.emplace_back(1, c);
    return cells;
  }
  std::size_t i = 0;
  while (i < text.size()) {
    while (i < text.size() && (text[i] == ' ' || text[i] == '\t' || text[i] == '|')) ++i;
    const std::size_t start = i;
    while (i < text.size() && text[i] != ' ' && text[i] != '\t' && text[i] != '|') ++i;
    if (i > start) cells.emplace_back(text.substr(start, i - start));
  }
  return cells;
}

inline constexpr std::size_t diagram_channels = 32;
using diagram_recorder = trace_recorder<std::size_t{1} << 20, diagram_channels>;

}  // namespace detail

/// One signal of a diagram or table: driven (written before each cycle) or expected
/// (recorded after it and compared). Made by drive() and expect().
struct lane {
  std::string name;
  bool driven = false;
  bool boolean = false;
  std::vector<std::string> cells;  // per cycle; "." any
  void* variable = nullptr;
  bool (*write)(void* variable, std::string_view token) = nullptr;
  std::optional<std::string> (*normalize)(std::string_view token) = nullptr;  // token -> to_text
  bool (*record)(detail::diagram_recorder& recorder, std::string_view name, void* variable) = nullptr;
  bool is_time = false;  // TIME/LTIME: a table column NAME_ms
};

namespace detail {
template <class V>
lane make_lane(std::string_view name, V& variable, std::string_view picture, bool driven) {
  using W = std::remove_cvref_t<V>;
  using T = forced_value_t<W>;
  lane l;
  l.name = std::string(name);
  l.driven = driven;
  l.boolean = std::is_same_v<T, BOOL>;
  l.is_time = std::is_same_v<T, TIME> || std::is_same_v<T, LTIME>;
  l.cells = cells_of(picture, l.boolean);
  l.variable = const_cast<W*>(&variable);
  l.write = [](void* v, std::string_view token) {
    const std::optional<T> value = parse_token<T>(token);
    if (value) write_variable(*static_cast<W*>(v), *value);
    return value.has_value();
  };
  l.normalize = [](std::string_view token) -> std::optional<std::string> {
    const std::optional<T> value = parse_token<T>(token);
    if (!value) return std::nullopt;
    return text_of(*value);
  };
  l.record = [](diagram_recorder& recorder, std::string_view n, void* v) {
    return recorder.add(n, *static_cast<W*>(v));
  };
  return l;
}
}  // namespace detail

/// A lane the diagram writes before each cycle: `picture` as for expect(); `.` keeps the value.
template <class V>
lane drive(std::string_view name, V& variable, std::string_view picture = {}) {
  static_assert(!std::is_const_v<V>, "iecoop: a driven lane writes its variable; give a variable, not a constant");
  return detail::make_lane(name, variable, picture, true);
}

/// A lane the diagram records after each cycle and compares with `picture`.
template <class V>
lane expect(std::string_view name, const V& variable, std::string_view picture = {}) {
  return detail::make_lane(name, variable, picture, false);
}

/// What run_diagram() and run_table() found: TRUE if every expected cell matched. Printed in
/// a failed check: the lanes aligned, expected above actual, the first difference marked.
struct diagram_result {
  bool ok = true;
  std::string report;
  explicit operator bool() const noexcept { return ok; }
  friend std::ostream& operator<<(std::ostream& os, const diagram_result& r) { return os << r.report; }
};

namespace detail {

/// Lays out the lanes as columns of cycles, expected above actual, with the first differing
/// cycle marked.
inline std::string layout(const std::vector<lane>& lanes, const std::vector<std::vector<std::string>>& actual,
                          std::size_t cycles, std::size_t first_difference, const std::string& heading) {
  bool pictures = true;
  for (const lane& l : lanes) pictures = pictures && l.boolean;
  // A cell as its value's text (`10` in a TIME lane: T#10ms), so that expected and actual align.
  const auto cell = [&](const lane& l, std::size_t i) -> std::string {
    if (i >= l.cells.size() || l.cells[i] == ".") return ".";
    const std::optional<std::string> text = l.normalize(l.cells[i]);
    return text ? *text : l.cells[i];
  };
  const auto shown = [&](const lane& l, const std::string& text) -> std::string {
    if (!l.boolean || !pictures) return text;
    return text == "TRUE" ? "#" : text == "FALSE" ? "_" : text;
  };
  std::vector<std::size_t> width(cycles, 1);
  for (std::size_t i = 0; i < cycles; ++i) {
    std::size_t w = std::to_string(i).size();
    if (pictures) w = 1;
    for (std::size_t k = 0; k < lanes.size(); ++k) {
      w = std::max(w, shown(lanes[k], cell(lanes[k], i)).size());
      if (!lanes[k].driven && i < actual[k].size()) w = std::max(w, shown(lanes[k], actual[k][i]).size());
    }
    width[i] = w;
  }
  // The names' column, with a space after the longest name; then "expect " or "actual ".
  std::size_t name_width = 5;
  for (const lane& l : lanes) name_width = std::max(name_width, l.name.size());
  ++name_width;
  const std::string sep = pictures ? "" : " ";
  const auto row = [&](std::string label, const auto& text_of_cycle) {
    label.resize(name_width + 7, ' ');
    std::string line = label;
    for (std::size_t i = 0; i < cycles; ++i) {
      std::string t = text_of_cycle(i);
      if (i > 0) line += sep;
      t.resize(width[i], ' ');
      line += t;
    }
    while (!line.empty() && line.back() == ' ') line.pop_back();
    return line + "\n";
  };
  std::string out = heading + "\n";
  out += row("cycle", [&](std::size_t i) { return pictures ? std::to_string(i % 10) : std::to_string(i); });
  for (std::size_t k = 0; k < lanes.size(); ++k) {
    const lane& l = lanes[k];
    if (l.driven) {
      out += row(l.name, [&](std::size_t i) { return shown(l, cell(l, i)); });
      continue;
    }
    std::string name = l.name;
    name.resize(name_width, ' ');
    out += row(name + "expect", [&](std::size_t i) { return shown(l, cell(l, i)); });
    out += row(std::string(name_width, ' ') + "actual",
               [&](std::size_t i) { return i < actual[k].size() ? shown(l, actual[k][i]) : std::string(); });
  }
  if (first_difference < cycles) {
    std::size_t column = name_width + 7;
    for (std::size_t i = 0; i < first_difference; ++i) column += width[i] + sep.size();
    out += std::string(column, ' ') + "^\n";
  }
  return out;
}

// Compares lane k's cell i with the recorded text; TRUE if it matches (or is "." / beyond the lane).
inline bool cell_matches(const lane& l, std::size_t i, const std::string& actual, std::string& error) {
  if (i >= l.cells.size() || l.cells[i] == ".") return true;
  const std::optional<std::string> expected = l.normalize(l.cells[i]);
  if (!expected) {
    error = "iecoop: '" + l.cells[i] + "' in lane " + l.name + " is no value of its type";
    return false;
  }
  return *expected == actual;
}

/// The recorder for the lanes, on the heap (a megabyte: not for a test's stack).
inline std::unique_ptr<diagram_recorder> record_lanes(std::vector<lane>& lanes, std::string& error) {
  auto recorder = std::make_unique<diagram_recorder>();
  for (lane& l : lanes) {
    if (!l.driven && !l.record(*recorder, l.name, l.variable)) error = "iecoop: too many lanes (at most 32)";
  }
  recorder->set_mode(trace_mode::every_cycle);
  recorder->start();
  return recorder;
}

inline std::string recorded_text(const trace_view& view, std::size_t sample, std::size_t channel) {
  char out[128];
  const char* end = view.text(sample, channel, out);
  return std::string(out, static_cast<std::size_t>(end - out));
}

}  // namespace detail

/**
 * Runs as many cycles of `run` (testing::cycles or testing::plc) as the longest lane has
 * cells: before each, the driven lanes' cells are written; after it, the expected lanes are
 * recorded. Use it in CHECK or REQUIRE.
 */
template <class Driver, class... Lanes>
[[nodiscard]] diagram_result run_diagram(Driver& run, Lanes&&... lane_list) {
  std::vector<lane> lanes{std::forward<Lanes>(lane_list)...};
  std::string error;
  std::size_t cycles = 0;
  for (const lane& l : lanes) cycles = std::max(cycles, l.cells.size());
  auto recorder = detail::record_lanes(lanes, error);
  run.on_step([](void* r) { static_cast<detail::diagram_recorder*>(r)->sample(cycle_clock::now(), 0); },
              recorder.get());
  for (std::size_t i = 0; i < cycles && error.empty(); ++i) {
    for (lane& l : lanes) {
      if (l.driven && i < l.cells.size() && l.cells[i] != "." && !l.write(l.variable, l.cells[i])) {
        error = "iecoop: '" + l.cells[i] + "' in lane " + l.name + " is no value of its type";
      }
    }
    run.step();
  }
  run.on_step(nullptr, nullptr);

  const trace_view view = recorder->view();
  std::vector<std::vector<std::string>> actual(lanes.size());
  std::size_t first = cycles;
  std::string differing;
  std::size_t channel = 0;
  for (std::size_t k = 0; k < lanes.size(); ++k) {
    if (lanes[k].driven) continue;
    for (std::size_t i = 0; i < view.size(); ++i) {
      actual[k].push_back(detail::recorded_text(view, i, channel));
      if (i < first && !detail::cell_matches(lanes[k], i, actual[k].back(), error)) {
        first = i;
        differing = lanes[k].name;
      }
    }
    ++channel;
  }
  diagram_result result;
  result.ok = error.empty() && first == cycles && view.size() == cycles;
  std::string heading = "timing diagram: ";
  if (!error.empty()) {
    heading += error;
  } else if (view.size() != cycles) {
    heading += std::to_string(view.size()) + " of " + std::to_string(cycles) + " cycles ran (a fault stopped them?)";
  } else if (first < cycles) {
    heading += differing + " differs from cycle " + std::to_string(first) + " (" +
               detail::text_of(TIME(view.time(first))) + ")";
  } else {
    heading += "as expected";
  }
  result.report = detail::layout(lanes, actual, cycles, result.ok ? cycles : first, heading);
  return result;
}

namespace detail {

/// The fields of a CSV line; the last column (a note) takes the rest of the line.
inline std::vector<std::string> csv_fields(std::string_view line, std::size_t columns) {
  std::vector<std::string> fields;
  while (fields.size() + 1 < columns) {
    const std::size_t comma = line.find(',');
    if (comma == std::string_view::npos) break;
    fields.emplace_back(line.substr(0, comma));
    line.remove_prefix(comma + 1);
  }
  fields.emplace_back(line);
  for (std::string& f : fields) {
    while (!f.empty() && (f.back() == '\r' || f.back() == ' ')) f.pop_back();
    while (!f.empty() && f.front() == ' ') f.erase(f.begin());
  }
  return fields;
}

}  // namespace detail

/**
 * A data-driven test from a CSV table in iecoop-replay's format: a header `cycle,time_ms,`
 * then the columns (a lane's name, or NAME_ms for a TIME lane, in ms), optionally `note`;
 * BOOL as 0/1. Per row: the time is set to time_ms (testing::cycles; testing::plc runs
 * cycles until its time is time_ms), the driven lanes' columns are written, one cycle runs,
 * the expected lanes' columns are compared. The lanes are drive(name, variable) and
 * expect(name, variable) without pictures.
 *
 *     CHECK(testing::run_table(run, testing::read_file("ton.trace.csv"),
 *                              testing::drive("IN", tmr.IN), testing::drive("PT", tmr.PT),
 *                              testing::expect("Q", tmr.Q), testing::expect("ET", tmr.ET)));
 */
template <class Driver, class... Lanes>
[[nodiscard]] diagram_result run_table(Driver& run, std::string_view csv, Lanes&&... lane_list) {
  std::vector<lane> lanes{std::forward<Lanes>(lane_list)...};
  diagram_result result;
  const auto fail = [&](std::string why) {
    result.ok = false;
    result.report = "table: " + std::move(why);
    return result;
  };
  if (csv.starts_with("\xEF\xBB\xBF")) csv.remove_prefix(3);  // a UTF-8 byte order mark
  std::vector<std::string_view> lines;
  while (!csv.empty()) {
    const std::size_t end = csv.find('\n');
    const std::string_view line = csv.substr(0, end);
    if (!line.empty() && line != "\r") lines.push_back(line);
    csv.remove_prefix(end == std::string_view::npos ? csv.size() : end + 1);
  }
  if (lines.empty()) return fail("no header line");
  const std::vector<std::string> header = detail::csv_fields(lines[0], static_cast<std::size_t>(-1));
  std::size_t time_column = header.size();
  std::vector<std::size_t> column(lanes.size(), header.size());
  for (std::size_t c = 0; c < header.size(); ++c) {
    if (header[c] == "time_ms") time_column = c;
    for (std::size_t k = 0; k < lanes.size(); ++k) {
      if (header[c] == lanes[k].name || (lanes[k].is_time && header[c] == lanes[k].name + "_ms")) column[k] = c;
    }
  }
  if (time_column == header.size()) return fail("no time_ms column");
  for (std::size_t k = 0; k < lanes.size(); ++k) {
    if (column[k] == header.size()) return fail("no column " + lanes[k].name + (lanes[k].is_time ? "_ms" : ""));
  }

  // Each row's cells go into the lanes, as a diagram's do; then it is one.
  std::vector<std::vector<std::string>> rows;
  for (std::size_t r = 1; r < lines.size(); ++r) {
    rows.push_back(detail::csv_fields(lines[r], header.size()));
    if (rows.back().size() != header.size()) return fail("line " + std::to_string(r + 1) + " has too few fields");
    for (std::size_t k = 0; k < lanes.size(); ++k) lanes[k].cells.push_back(rows.back()[column[k]]);
  }
  std::string error;
  auto recorder = detail::record_lanes(lanes, error);
  for (std::size_t r = 0; r < rows.size() && error.empty(); ++r) {
    const std::optional<LTIME> time = detail::parse_token<LTIME>(rows[r][time_column]);
    if (!time) {
      error = "time_ms '" + rows[r][time_column] + "' in line " + std::to_string(r + 2) + " is no number";
      break;
    }
    if constexpr (requires { run.set_now(*time); }) {
      run.set_now(*time);
    } else {
      if (*time > run.now()) run.advance(*time - run.now());
    }
    for (lane& l : lanes) {
      if (l.driven && !l.write(l.variable, l.cells[r])) {
        error = "'" + l.cells[r] + "' in column " + l.name + ", line " + std::to_string(r + 2) +
                ", is no value of its type";
      }
    }
    // Only the row's own cycle is recorded (not those that brought the time to it).
    run.on_step([](void* rec) { static_cast<detail::diagram_recorder*>(rec)->sample(cycle_clock::now(), 0); },
                recorder.get());
    run.step();
    run.on_step(nullptr, nullptr);
  }
  if (!error.empty()) return fail(error);

  const trace_view view = recorder->view();
  if (view.size() != rows.size()) {
    return fail(std::to_string(view.size()) + " of " + std::to_string(rows.size()) +
                " rows ran (a fault stopped them?)");
  }
  std::size_t channel = 0;
  std::string differences;
  std::size_t first = rows.size();
  for (std::size_t k = 0; k < lanes.size(); ++k) {
    if (lanes[k].driven) continue;
    for (std::size_t r = 0; r < rows.size(); ++r) {
      const std::string actual = detail::recorded_text(view, r, channel);
      if (detail::cell_matches(lanes[k], r, actual, error) || r > first) continue;
      if (r < first) differences.clear();
      first = r;
      const std::optional<std::string> expected = lanes[k].normalize(lanes[k].cells[r]);
      differences +=
          "\n  " + lanes[k].name + ": expected " + (expected ? *expected : lanes[k].cells[r]) + ", actual " + actual;
    }
    ++channel;
  }
  if (first == rows.size()) {
    result.report = "table: " + std::to_string(rows.size()) + " rows as expected";
    return result;
  }
  const std::size_t note_column = header.back() == "note" ? header.size() - 1 : header.size();
  std::string where = "line " + std::to_string(first + 2) + " (time_ms " + rows[first][time_column];
  if (note_column < header.size() && !rows[first][note_column].empty()) where += ", '" + rows[first][note_column] + "'";
  return fail(where + ") differs:" + differences + "\n  " + std::string(lines[first + 1]));
}

/// The text of the file at `path` (a CSV table next to the tests); empty if it cannot be read.
inline std::string read_file(const char* path) {
  std::string text;
  if (std::FILE* f = std::fopen(path, "rb")) {
    char buffer[4096];
    std::size_t n = 0;
    while ((n = std::fread(buffer, 1, sizeof buffer, f)) > 0) text.append(buffer, n);
    std::fclose(f);
  }
  return text;
}

}  // namespace iecoop::testing

#include <iecoop/detail/pop_macros.hpp>
