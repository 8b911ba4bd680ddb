// SPDX-License-Identifier: MIT
// iecoop/exchange/detail/mqtt_json.hpp — what an MQTT bridge writes: JSON strings and a
// channel's value as JSON, and the topics the channels' names become.
// IWYU pragma: private, include <iecoop/exchange/mqtt.hpp>
#pragma once

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <string>
#include <string_view>

#include <iecoop/config.hpp>
#include <iecoop/trace/channels.hpp>
#include <iecoop/types/literal_text.hpp>

#include <iecoop/detail/push_macros.hpp>

namespace iecoop::detail {

/// Appends `text` as a JSON string.
inline void mqtt_append_json_string(std::string& out, std::string_view text) {
  out += '"';
  for (const char c : text) {
    if (c == '"' || c == '\\') {
      out += '\\';
      out += c;
    } else if (static_cast<unsigned char>(c) < 0x20) {
      char escape[8];
      std::snprintf(escape, sizeof escape, "\\u%04x", static_cast<unsigned>(static_cast<unsigned char>(c)));
      out += escape;
    } else {
      out += c;
    }
  }
  out += '"';
}

/// IEC text as a string.
inline void mqtt_append_json_value(std::string& out, const trace_type& type, const std::byte* values,
                                   std::uint16_t offset) {
  const trace_value value = decode_trace_value(type, values, offset);
  char text[64];
  switch (type.kind) {
    case trace_kind::boolean: out += value.u != 0 ? "true" : "false"; return;
    case trace_kind::real:
      if (!std::isfinite(value.f)) {
        out += "null";
        return;
      }
      [[fallthrough]];
    case trace_kind::signed_integer:
    case trace_kind::unsigned_integer:
    case trace_kind::bit_string:
      out.append(text, static_cast<std::size_t>(type.text(text, values + offset) - text));
      return;
    default:
      mqtt_append_json_string(
          out, std::string_view(text, static_cast<std::size_t>(type.text(text, values + offset) - text)));
      return;
  }
}

/// Where a name may stand in a topic: not empty, no empty part between dots, no MQTT
/// wildcard or level separator.
inline bool mqtt_valid_name(std::string_view name) noexcept {
  if (name.empty() || name.front() == '.' || name.back() == '.') return false;
  for (std::size_t i = 0; i < name.size(); ++i) {
    const char c = name[i];
    if (c == '+' || c == '#' || c == '/' || c == '\0') return false;
    if (c == '.' && name[i + 1] == '.') return false;
  }
  return true;
}

/// `topic` is `name` with '/' for '.'.
inline bool mqtt_topic_names(std::string_view topic, std::string_view name) noexcept {
  if (topic.size() != name.size()) return false;
  for (std::size_t i = 0; i < name.size(); ++i) {
    if (topic[i] != (name[i] == '.' ? '/' : name[i])) return false;
  }
  return true;
}

inline void mqtt_append_topic_name(std::string& out, std::string_view name) {
  for (const char c : name) out += c == '.' ? '/' : c;
}

/// A channel's value as its bits, to compare with the one published last.
inline std::uint64_t mqtt_bits(const trace_type& type, const std::byte* values, std::uint16_t offset) noexcept {
  if (type.kind == trace_kind::boolean) return (std::to_integer<unsigned>(values[offset / 8]) >> (offset % 8)) & 1U;
  std::uint64_t bits = 0;
  std::memcpy(&bits, values + offset, type.bytes);
  return bits;
}

inline std::size_t mqtt_levels(std::string_view name) noexcept {
  return 1 + static_cast<std::size_t>(std::count(name.begin(), name.end(), '.'));
}

}  // namespace iecoop::detail

#include <iecoop/detail/pop_macros.hpp>
