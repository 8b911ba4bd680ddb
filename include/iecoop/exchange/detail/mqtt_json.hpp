// SPDX-License-Identifier: MIT
// iecoop/exchange/detail/mqtt_json.hpp — what an MQTT bridge writes: JSON strings and a
// channel's value as JSON, and the topics the channels' names become.
// IWYU pragma: private, include <iecoop/exchange/mqtt.hpp>
#pragma once

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <string>
#include <string_view>

#include <iecoop/config.hpp>
#include <iecoop/trace/channels.hpp>
#include <iecoop/types/literal_text.hpp>

#include <iecoop/detail/push_macros.hpp>

namespace iecoop::detail {

/// The length of the well-formed UTF-8 sequence (RFC 3629: no overlong form, no surrogate,
/// nothing above U+10FFFF) that starts `text` at `i`, 0 if none starts there.
inline std::size_t utf8_sequence(std::string_view text, std::size_t i) noexcept {
  if (i >= text.size()) return 0;
  // A byte past the end reads as 0, which continues no sequence.
  const auto byte = [&](std::size_t k) -> unsigned {
    return i + k < text.size() ? static_cast<unsigned char>(text[i + k]) : 0U;
  };
  const auto continuation = [&](std::size_t k, unsigned lo = 0x80, unsigned hi = 0xBF) {
    return byte(k) >= lo && byte(k) <= hi;
  };
  const unsigned b0 = byte(0);
  if (b0 < 0x80) return 1;
  if (b0 >= 0xC2 && b0 <= 0xDF) return continuation(1) ? 2 : 0;
  if (b0 == 0xE0) return continuation(1, 0xA0) && continuation(2) ? 3 : 0;
  if ((b0 >= 0xE1 && b0 <= 0xEC) || b0 == 0xEE || b0 == 0xEF) return continuation(1) && continuation(2) ? 3 : 0;
  if (b0 == 0xED) return continuation(1, 0x80, 0x9F) && continuation(2) ? 3 : 0;
  if (b0 == 0xF0) return continuation(1, 0x90) && continuation(2) && continuation(3) ? 4 : 0;
  if (b0 >= 0xF1 && b0 <= 0xF3) return continuation(1) && continuation(2) && continuation(3) ? 4 : 0;
  if (b0 == 0xF4) return continuation(1, 0x80, 0x8F) && continuation(2) && continuation(3) ? 4 : 0;
  return 0;
}

/// Appends at most the first `max_bytes` bytes of `text` as a JSON string that is always
/// valid: `"` and `\` escaped, control characters as \u00XX, well-formed UTF-8 copied, and each
/// byte that begins no well-formed sequence (Latin-1 text, a cut sequence, binary) as \ufffd,
/// the replacement character. The cut falls between characters, never inside one.
inline void mqtt_append_json_string(std::string& out, std::string_view text,
                                    std::size_t max_bytes = static_cast<std::size_t>(-1)) {
  out += '"';
  std::size_t i = 0;
  while (i < text.size()) {
    const std::size_t length = utf8_sequence(text, i);
    if (i + (length == 0 ? 1 : length) > max_bytes) break;
    if (length == 0) {
      out += "\\ufffd";
      ++i;
      continue;
    }
    const char c = text[i];
    if (c == '"' || c == '\\') {
      out += '\\';
      out += c;
    } else if (static_cast<unsigned char>(c) < 0x20) {
      static constexpr char hex[] = "0123456789abcdef";
      out += "\\u00";
      out += hex[static_cast<unsigned char>(c) >> 4];
      out += hex[static_cast<unsigned char>(c) & 0xF];
    } else {
      out.append(text.substr(i, length));
    }
    i += length;
  }
  out += '"';
}

/// How many bytes of a rejected command's payload its `/set/rejected` message repeats.
inline constexpr std::size_t mqtt_rejected_payload_bytes = 64;

/// The message of a rejected command: {"reason": ..., "type": ... (if known), "payload": the
/// payload's first mqtt_rejected_payload_bytes bytes, cut between characters}, valid JSON
/// whatever the payload's bytes.
inline void mqtt_rejection_message(std::string& out, std::string_view reason, std::string_view type_name,
                                   std::string_view payload) {
  out.assign("{\"reason\":");
  mqtt_append_json_string(out, reason);
  if (!type_name.empty()) {
    out += ",\"type\":";
    mqtt_append_json_string(out, type_name);
  }
  out += ",\"payload\":";
  mqtt_append_json_string(out, payload, mqtt_rejected_payload_bytes);
  out += '}';
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
