// SPDX-License-Identifier: MIT
// iecoop/trace/vcd.hpp — a trace as a Value Change Dump (IEEE 1364, clause 18), the format of
// GTKWave and every logic analyser and simulator:
//
//     std::ofstream file("shift.vcd");
//     write_vcd(trace.view(), [&](std::string_view s) { file << s; });
//     // $ gtkwave shift.vcd
//
// Each channel is a variable in the scopes its name gives (`IO_PRG.tJam.IN`: scope IO_PRG,
// scope tJam, variable IN), inside a top scope (options.top_scope):
//   BOOL                          wire 1
//   SINT .. LINT, signed enums    integer 8 .. 64 (two's complement)
//   USINT .. ULINT, BYTE .. LWORD reg 8 .. 64 (and unsigned enums)
//   REAL, LREAL                   real 64, the shortest text that reads back as the same
//                                 REAL / LREAL (`0.1`, not the double nearest 0.1F)
//   TIME, LTIME                   reg 32 / reg 64, a count of ms / ns (options.time_as_real:
//                                 real 64, in seconds, exact: `1.5`, `0.000000001`)
//   dates and times of day        reg 32 / 64, a count of their unit
// The timescale is the largest power of ten (1 ns .. 1 s) that divides every sample's time,
// so a 1 ms task gives `$timescale 1 ms $end` and times in cycles of its clock. Times are the
// cycle clock's; the dump starts with every value at the first sample ($dumpvars) and then
// lists the values that changed, sample by sample, and ends with the last sample's time.
// Channels are declared in the order added; a scope opens where a channel's scope differs
// from the one before (give channels of one block one after the other, as add_pins does).
// IWYU pragma: private, include <iecoop/trace.hpp>
#pragma once

#include <cstddef>
#include <cstdint>
#include <string_view>

#include <iecoop/config.hpp>
#include <iecoop/detail/constant_division.hpp>
#include <iecoop/trace/channels.hpp>
#include <iecoop/trace/put_text.hpp>
#include <iecoop/trace/view.hpp>

#include <iecoop/detail/push_macros.hpp>

namespace iecoop {

/// How write_vcd writes a trace.
struct vcd_options {
  /// The scope every channel is in (GTKWave shows it as the root of the signal tree).
  std::string_view top_scope = "iecoop";
  /// TIME and LTIME as real variables in seconds, instead of integer counts of ms / ns.
  bool time_as_real = false;
};

namespace detail {

/// The identifier code of variable n: printable ASCII from '!' to '~', base 94.
template <class Put>
void put_vcd_id(Put& put, std::size_t n) {
  char id[8];
  std::size_t length = 0;
  do {
    id[length++] = static_cast<char>('!' + n % 94);
    n /= 94;
  } while (n != 0 && length < sizeof id);
  put(std::string_view(id, length));
}

/// A name as VCD allows it: no white space (replaced by '_').
template <class Put>
void put_vcd_name(Put& put, std::string_view name) {
  std::size_t start = 0;
  for (std::size_t i = 0; i <= name.size(); ++i) {
    if (i == name.size() || name[i] == ' ' || name[i] == '\t' || name[i] == '\n' || name[i] == '\r') {
      put(std::string_view(name.data() + start, i - start));  // not substr(): it may throw
      if (i < name.size()) put("_");
      start = i + 1;
    }
  }
}

/// The i-th dot-separated part of a scope, and how many there are.
constexpr std::string_view scope_part(std::string_view scope, std::size_t index) noexcept {
  for (std::size_t i = 0; i < index; ++i) {
    const std::size_t dot = scope.find('.');
    if (dot == std::string_view::npos) return {};
    scope.remove_prefix(dot + 1);
  }
  const std::size_t dot = scope.find('.');
  return std::string_view(scope.data(), dot == std::string_view::npos ? scope.size() : dot);
}
constexpr std::size_t scope_depth(std::string_view scope) noexcept {
  if (scope.empty()) return 0;
  std::size_t depth = 1;
  for (const char c : scope) depth += c == '.' ? 1U : 0U;
  return depth;
}
/// How many leading parts two scopes share.
constexpr std::size_t common_scope_depth(std::string_view a, std::string_view b) noexcept {
  const std::size_t da = scope_depth(a);
  const std::size_t db = scope_depth(b);
  std::size_t n = 0;
  while (n < da && n < db && scope_part(a, n) == scope_part(b, n)) ++n;
  return n;
}

constexpr bool vcd_is_real(const trace_type& type, const vcd_options& options) noexcept {
  return type.kind == trace_kind::real || (options.time_as_real && type.kind == trace_kind::duration);
}

/// One value in VCD: `1!`, `b101 "`, `r1.5 #`. `real_text` is the IEC text of a REAL or
/// LREAL value (the shortest text that reads back as the same value: the type's own text, so
/// that std::to_chars for floating point, which lives in the compiled libstdc++, is linked only
/// where a REAL or LREAL is traced, as REAL_TO_STRING does).
template <class Put>
void put_vcd_value(Put& put, const trace_type& type, const trace_value& value, std::string_view real_text,
                   std::size_t id, const vcd_options& options) {
  if (type.kind == trace_kind::boolean) {
    put(value.u != 0 ? "1" : "0");
  } else if (vcd_is_real(type, options)) {
    put("r");
    if (type.kind == trace_kind::real) {
      put(real_text);
    } else {
      put_seconds(put, value.u * type.ns_per_count);  // exact: whole seconds, then the fraction
    }
    put(" ");
  } else {
    // Two's complement in the value's own width; leading zeros left out.
    const std::size_t bits = type.bytes * 8U;
    std::uint64_t u = value.u;
    if (bits < 64) u &= (std::uint64_t{1} << bits) - 1;
    char digits[65];
    std::size_t length = 0;
    digits[length++] = 'b';
    bool started = false;
    for (std::size_t bit = bits; bit-- > 0;) {
      const bool one = ((u >> bit) & 1U) != 0;
      if (one) started = true;
      if (started) digits[length++] = one ? '1' : '0';
    }
    if (!started) digits[length++] = '0';
    put(std::string_view(digits, length));
    put(" ");
  }
  put_vcd_id(put, id);
  put("\n");
}

/// Sample i's value of channel c in VCD.
template <class Put>
void put_vcd_sample_value(Put& put, const trace_view& view, std::size_t i, std::size_t c, const vcd_options& options) {
  const trace_type& type = *view.channels()[c].type;
  char text[64];  // a REAL's or LREAL's text: at most max_text_length<LREAL>, 32 characters
  std::string_view real_text{};
  if (type.kind == trace_kind::real) {
    real_text = std::string_view(text, static_cast<std::size_t>(view.text(i, c, text) - text));
  }
  put_vcd_value(put, type, view.value(i, c), real_text, c, options);
}

}  // namespace detail

/// Writes `view` as a VCD file through `put(std::string_view)`.
template <class Put>
void write_vcd(const trace_view& view, Put&& put, const vcd_options& options = {}) {
  const auto channels = view.channels();

  // The timescale: the largest power of ten of nanoseconds (at most 1 s) dividing every time.
  // (The unit is known only here: detail::divide_u64, which needs no 64-bit division routine on a
  // 32-bit core.)
  std::uint32_t unit = 1'000'000'000;
  const auto in_units = [&unit](LTIME t) { return detail::divide_u64(t.count(), unit); };
  for (std::size_t i = 0; i < view.size() && unit > 1; ++i) {
    while (unit > 1 && in_units(view.time(i)) * unit != view.time(i).count()) unit /= 10;
  }
  static constexpr std::string_view scales[] = {"1 ns",   "10 ns", "100 ns", "1 us",   "10 us",
                                                "100 us", "1 ms",  "10 ms",  "100 ms", "1 s"};
  std::size_t scale = 0;
  for (std::uint32_t u = unit; u > 1; u /= 10) ++scale;

  put("$version iecoop trace recorder $end\n");
  if (view.trigger_index() != trace_view::no_trigger) {
    put("$comment trigger at cycle ");
    detail::put_unsigned(put, view.cycle(view.trigger_index()));
    put(", time ");
    detail::put_unsigned(put, in_units(view.time(view.trigger_index())));
    put(" $end\n");
  }
  put("$timescale ");
  put(scales[scale]);
  put(" $end\n$scope module ");
  detail::put_vcd_name(put, options.top_scope);
  put(" $end\n");
  std::string_view open_scope{};
  for (std::size_t c = 0; c < channels.size(); ++c) {
    const trace_channel& channel = channels[c];
    const std::size_t keep = detail::common_scope_depth(open_scope, channel.scope);
    for (std::size_t d = detail::scope_depth(open_scope); d > keep; --d) put("$upscope $end\n");
    for (std::size_t d = keep; d < detail::scope_depth(channel.scope); ++d) {
      put("$scope module ");
      detail::put_vcd_name(put, detail::scope_part(channel.scope, d));
      put(" $end\n");
    }
    open_scope = channel.scope;
    const trace_type& type = *channel.type;
    put("$var ");
    if (type.kind == trace_kind::boolean) {
      put("wire 1 ");
    } else if (detail::vcd_is_real(type, options)) {
      put("real 64 ");
    } else {
      put(type.is_signed ? "integer " : "reg ");
      detail::put_unsigned(put, type.bytes * 8U);
      put(" ");
    }
    detail::put_vcd_id(put, c);
    put(" ");
    detail::put_vcd_name(put, channel.name);
    put(" $end\n");
  }
  for (std::size_t d = detail::scope_depth(open_scope); d > 0; --d) put("$upscope $end\n");
  put("$upscope $end\n$enddefinitions $end\n");
  if (view.empty()) return;

  // The first sample in full, then the changes.
  put("#");
  detail::put_unsigned(put, in_units(view.time(0)));
  put("\n$dumpvars\n");
  for (std::size_t c = 0; c < channels.size(); ++c) {
    detail::put_vcd_sample_value(put, view, 0, c, options);
  }
  put("$end\n");
  bool last_written = view.size() == 1;
  for (std::size_t i = 1; i < view.size(); ++i) {
    if (view.same_values(i, i - 1)) continue;
    put("#");
    detail::put_unsigned(put, in_units(view.time(i)));
    put("\n");
    for (std::size_t c = 0; c < channels.size(); ++c) {
      if (!view.same_value(i, i - 1, c)) detail::put_vcd_sample_value(put, view, i, c, options);
    }
    last_written = i == view.size() - 1;
  }
  if (!last_written) {
    put("#");
    detail::put_unsigned(put, in_units(view.time(view.size() - 1)));
    put("\n");
  }
}

}  // namespace iecoop

#include <iecoop/detail/pop_macros.hpp>
