// SPDX-License-Identifier: MIT
// iecoop/trace/csv.hpp — a trace as CSV in iecoop-replay's format: the header
// `cycle,time_ms,<channels...>` and one row per sample. BOOL is 0 or 1, integers, bit strings
// and enumerations are decimal numbers, REAL and LREAL the shortest text that reads back as the
// same value, TIME a whole number of milliseconds in a column named `<name>_ms` (LTIME: of
// nanoseconds, `<name>_ns`), dates their IEC literal (`D#2026-11-23`). A block's pins recorded
// without a scope (add_pins(block)) give the columns iecoop-replay reads as a stimulus.
//
//     std::ofstream file("shift.csv");
//     write_csv(trace.view(), [&](std::string_view s) { file << s; });
//
// time_ms is the cycle clock's time; a time that is no whole number of milliseconds is written
// with a fraction (`0.25`), which iecoop-replay does not read.
// IWYU pragma: private, include <iecoop/trace.hpp>
#pragma once

#include <cstddef>
#include <string_view>

#include <iecoop/config.hpp>
#include <iecoop/trace/channels.hpp>
#include <iecoop/trace/put_text.hpp>
#include <iecoop/trace/view.hpp>

#include <iecoop/detail/push_macros.hpp>

namespace iecoop {

namespace detail {

/// A CSV field: as it is, or quoted (with its quotes doubled) if it holds a comma, a quote
/// or a line break.
template <class Put>
void put_csv_field(Put& put, std::string_view text) {
  if (text.find_first_of(",\"\r\n") == std::string_view::npos) {
    put(text);
    return;
  }
  put("\"");
  for (std::size_t start = 0;;) {
    const std::size_t quote = text.find('"', start);
    // Up to the quote (or the end), the quote included; not substr(), which may throw.
    put(std::string_view(text.data() + start, (quote == std::string_view::npos ? text.size() : quote + 1) - start));
    if (quote == std::string_view::npos) break;
    put("\"");
    start = quote + 1;
  }
  put("\"");
}

/// The unit suffix of a duration's column.
constexpr std::string_view duration_suffix(const trace_type& type) noexcept {
  return type.ns_per_count == 1'000'000 ? "_ms" : type.ns_per_count == 1 ? "_ns" : "";
}

}  // namespace detail

/// Writes `view` as CSV through `put(std::string_view)`.
template <class Put>
void write_csv(const trace_view& view, Put&& put) {
  const auto channels = view.channels();
  put("cycle,time_ms");
  for (const trace_channel& channel : channels) {
    put(",");
    // The name, with the unit of a duration; quoted as a whole if it needs quotes.
    char name[256];
    std::size_t length = 0;
    bool fits = true;
    const auto append = [&](std::string_view part) {
      if (length + part.size() > sizeof name) {
        fits = false;
        return;
      }
      for (const char c : part) name[length++] = c;
    };
    put_channel_name(channel, append);
    if (channel.type->kind == trace_kind::duration) append(detail::duration_suffix(*channel.type));
    if (fits) {
      detail::put_csv_field(put, std::string_view(name, length));
    } else {
      put_channel_name(channel, put);  // a name too long to check for quotes is written as it is
    }
  }
  put("\n");
  for (std::size_t i = 0; i < view.size(); ++i) {
    detail::put_unsigned(put, view.cycle(i));
    put(",");
    detail::put_milliseconds(put, view.time(i).count());
    for (std::size_t c = 0; c < channels.size(); ++c) {
      put(",");
      const trace_type& type = *channels[c].type;
      if (type.kind == trace_kind::date_time || type.kind == trace_kind::real) {
        // The longest date text is 33 characters (LDT#...), an LREAL's 32.
        char text[64];
        put(std::string_view(text, static_cast<std::size_t>(view.text(i, c, text) - text)));
      } else {
        detail::put_number(put, view.value(i, c));
      }
    }
    put("\n");
  }
}

}  // namespace iecoop

#include <iecoop/detail/pop_macros.hpp>
