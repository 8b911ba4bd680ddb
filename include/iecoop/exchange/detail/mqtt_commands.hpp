// SPDX-License-Identifier: MIT
// iecoop/exchange/detail/mqtt_commands.hpp — an MQTT bridge's commands: which variables a
// command writes and how, and a command's payload (a bare JSON scalar or IEC literal, a JSON
// string, or {"value": ...}) read into a value of the variable's type, with the reason when not.
// IWYU pragma: private, include <iecoop/exchange/mqtt.hpp>
#pragma once

#include <cstddef>
#include <cstdint>
#include <string_view>
#include <type_traits>

#include <iecoop/config.hpp>
#include <iecoop/detail/scalar_access.hpp>
#include <iecoop/io/located.hpp>
#include <iecoop/pou/variables.hpp>
#include <iecoop/types/detail/value_operators.hpp>
#include <iecoop/types/elementary.hpp>
#include <iecoop/types/enumeration.hpp>
#include <iecoop/types/literal_text.hpp>
#include <iecoop/types/time.hpp>

#include <iecoop/detail/push_macros.hpp>

namespace iecoop::detail {

/// The types a command writes.
template <class T>
concept mqtt_commandable = std::is_same_v<T, BOOL> || AnyInteger<T> || AnyReal<T> || std::is_same_v<T, TIME> ||
                           std::is_same_v<T, LTIME> || Enumeration<T>;

enum class mqtt_target_kind { plain, wrapper, located_input, in_out, property, read_only, unsupported };

/// How a command writes a variable of type W.
template <class W>
constexpr mqtt_target_kind mqtt_target_of() noexcept {
  if constexpr (mqtt_commandable<W>) {
    return mqtt_target_kind::plain;
  } else if constexpr (is_located<W>::value) {
    if constexpr (W::address.area == io_area::input) {
      return mqtt_target_kind::located_input;
    } else if constexpr (mqtt_commandable<typename W::value_type>) {
      return mqtt_target_kind::wrapper;
    } else {
      return mqtt_target_kind::unsupported;
    }
  } else if constexpr (is_in_out<W>::value) {
    return mqtt_target_kind::in_out;
  } else if constexpr (is_read_only<W>::value) {
    return mqtt_target_kind::read_only;
  } else if constexpr (requires(const W& w) { w.monitor(); }) {
    return mqtt_target_kind::property;
  } else if constexpr (value_wrapper<W> && requires { typename W::value_type; }) {
    if constexpr (mqtt_commandable<typename W::value_type> && std::is_assignable_v<W&, const typename W::value_type&>) {
      return mqtt_target_kind::wrapper;
    } else {
      return mqtt_target_kind::unsupported;
    }
  } else {
    return mqtt_target_kind::unsupported;
  }
}

template <class W, mqtt_target_kind = mqtt_target_of<W>()>
struct mqtt_target_value {
  using type = W;
};
template <class W>
struct mqtt_target_value<W, mqtt_target_kind::wrapper> {
  using type = typename W::value_type;
};
/// The value type a command for a variable of type W parses.
template <class W>
using mqtt_value_t = typename mqtt_target_value<W>::type;

/// A value's number, for a command's range.
template <class T>
constexpr auto mqtt_number(T value) noexcept {
  if constexpr (AnyDuration<T>) {
    return value.count();
  } else {
    return value.value();
  }
}

/// The value of an IEC literal text as a T: nullptr, or why not.
template <class T>
const char* mqtt_parse(std::string_view text, T& out) noexcept {
  const auto take = [&](const auto& result) -> const char* {
    if (!result) return describe(result.error());
    out = result.value_or(T{});
    return nullptr;
  };
  if constexpr (std::is_same_v<T, BOOL>) {
    return take(parse_bool(text));
  } else if constexpr (AnyInteger<T>) {
    return take(parse_integer<T>(text));
  } else if constexpr (AnyReal<T>) {
    return take(parse_real<T>(text));
  } else if constexpr (std::is_same_v<T, TIME>) {
    return take(parse_time(text));
  } else if constexpr (std::is_same_v<T, LTIME>) {
    return take(parse_ltime(text));
  } else {
    const parse_result<T> result = parse_enum<T>(text);
    if (!result) return describe(result.error());
    const T value = result.value_or(T{});
    if constexpr (has_components<T>) {
      if (!is_component(value)) return "no component of the enumeration has this value";
    }
    out = value;
    return nullptr;
  }
}

inline constexpr std::size_t mqtt_max_payload = 256;

/// Where a command's IEC literal text is in its payload: a bare JSON scalar or IEC literal
/// (`true`, `42`, `16#FF`, `T#2s`), a JSON string (`"T#2s"`, `"Run"`), or an object with one
/// member "value" holding either. A JSON string's escapes are undone into `buffer`.
struct mqtt_literal {
  std::string_view text;
  const char* error = nullptr;  ///< why the payload is malformed
};

inline bool mqtt_space(char c) noexcept { return c == ' ' || c == '\t' || c == '\n' || c == '\r'; }

inline std::string_view mqtt_trim(std::string_view s) noexcept {
  while (!s.empty() && mqtt_space(s.front())) s.remove_prefix(1);
  while (!s.empty() && mqtt_space(s.back())) s.remove_suffix(1);
  return s;
}

/// Reads the JSON string at s[i] == '"' into `out` (its escapes undone; ASCII only); i ends
/// after the closing quote. nullptr, or why it is malformed.
inline const char* mqtt_json_string(std::string_view s, std::size_t& i, char* out, std::size_t capacity,
                                    std::size_t& length) noexcept {
  length = 0;
  ++i;  // the opening quote
  for (; i < s.size(); ++i) {
    char c = s[i];
    if (c == '"') {
      ++i;
      return nullptr;
    }
    if (static_cast<unsigned char>(c) < 0x20) return "a control character in a JSON string";
    if (c == '\\') {
      if (++i == s.size()) break;
      switch (s[i]) {
        case '"': c = '"'; break;
        case '\\': c = '\\'; break;
        case '/': c = '/'; break;
        case 'b': c = '\b'; break;
        case 'f': c = '\f'; break;
        case 'n': c = '\n'; break;
        case 'r': c = '\r'; break;
        case 't': c = '\t'; break;
        case 'u': {
          if (s.size() - i < 5) return "a \\u escape needs four hex digits";
          unsigned code = 0;
          for (std::size_t k = 1; k <= 4; ++k) {
            const int d = digit_value(s[i + k]);
            if (d > 15) return "a \\u escape needs four hex digits";
            code = code * 16 + static_cast<unsigned>(d);
          }
          if (code >= 0x80) return "a command's text is ASCII";
          c = static_cast<char>(code);
          i += 4;
          break;
        }
        default: return "an unknown escape in a JSON string";
      }
    }
    if (length == capacity) return "the text is too long";
    out[length++] = c;
  }
  return "a JSON string without its closing quote";
}

inline mqtt_literal mqtt_command_literal(std::string_view payload, char* buffer, std::size_t capacity) noexcept {
  const std::string_view s = mqtt_trim(payload);
  if (s.empty()) return {{}, "an empty payload"};
  std::size_t length = 0;
  if (s.front() == '"') {
    std::size_t i = 0;
    if (const char* error = mqtt_json_string(s, i, buffer, capacity, length)) return {{}, error};
    if (i != s.size()) return {{}, "text after the JSON string"};
    return {std::string_view(buffer, length), nullptr};
  }
  if (s.front() != '{') {
    if (s == "null") return {{}, "null is no value"};
    return {s, nullptr};
  }
  // {"value": <scalar>}
  const char* const malformed = "malformed JSON: a command object is {\"value\": <value>}";
  std::size_t i = 1;
  const auto skip = [&] {
    while (i < s.size() && mqtt_space(s[i])) ++i;
  };
  skip();
  if (i == s.size() || s[i] != '"') return {{}, malformed};
  char key[8];
  std::size_t key_length = 0;
  if (mqtt_json_string(s, i, key, sizeof key, key_length) != nullptr) return {{}, malformed};
  if (std::string_view(key, key_length) != "value") return {{}, "a command object has one member, \"value\""};
  skip();
  if (i == s.size() || s[i] != ':') return {{}, malformed};
  ++i;
  skip();
  if (i == s.size()) return {{}, malformed};
  std::string_view text;
  if (s[i] == '"') {
    if (const char* error = mqtt_json_string(s, i, buffer, capacity, length)) return {{}, error};
    text = std::string_view(buffer, length);
  } else {
    const std::size_t first = i;
    while (i < s.size() && !mqtt_space(s[i]) && s[i] != ',' && s[i] != '}' && s[i] != '{' && s[i] != '[') ++i;
    text = s.substr(first, i - first);
    if (text.empty()) return {{}, malformed};
    if (text == "null") return {{}, "null is no value"};
  }
  skip();
  if (i < s.size() && s[i] == ',') return {{}, "a command object has one member, \"value\""};
  if (i == s.size() || s[i] != '}') return {{}, malformed};
  ++i;
  if (i != s.size()) return {{}, "text after the JSON object"};
  return {text, nullptr};
}

}  // namespace iecoop::detail

#include <iecoop/detail/pop_macros.hpp>
