// What iecoop's fuzz targets share: checking a property (a broken one stops the run, and libFuzzer
// keeps the input as a crash), and writing a value's text into a buffer of exactly
// max_text_length characters, so that AddressSanitizer sees a write past it.
#pragma once

#include <iecoop/fmt.hpp>
#include <iecoop/iecoop.hpp>
#include <iecoop/ostream.hpp>

#include <fmt/format.h>

#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <memory>
#include <sstream>
#include <string>
#include <string_view>

namespace iecoop_fuzz {

/// The input's bytes as text.
inline std::string_view as_text(const std::uint8_t* data, std::size_t size) noexcept {
  return {reinterpret_cast<const char*>(data), size};
}

/// The text with its control characters and bytes above 0x7E as \xNN, for a report.
inline std::string printable(std::string_view text) {
  std::string result;
  for (const char c : text) {
    const auto byte = static_cast<unsigned char>(c);
    if (byte < 0x20 || byte > 0x7E || c == '\\') {
      char escaped[5];
      std::snprintf(escaped, sizeof escaped, "\\x%02X", byte);
      result += escaped;
    } else {
      result += c;
    }
  }
  return result;
}

/// Stops the run where `holds` is false: the property `what` is broken for `detail` (the text
/// concerned, shown escaped).
inline void require(bool holds, const char* what, std::string_view detail = {}) {
  if (holds) return;
  std::fprintf(stderr, "iecoop fuzz: property broken: %s\n  with: \"%s\"\n", what, printable(detail).c_str());
  std::abort();
}

/// A value of type U read from `size` bytes at `data` (missing bytes are 0).
template <class U>
U load(const std::uint8_t* data, std::size_t size) noexcept {
  U value{};
  std::memcpy(&value, data, size < sizeof value ? size : sizeof value);
  return value;
}

/// to_text(value), written into a heap buffer of exactly max_text_length<T> characters: a write
/// past it is AddressSanitizer's heap-buffer-overflow. The other ways to the text (operator<<,
/// fmt, convert to STRING, which use buffers of that size on the stack) must write the same.
template <class T>
std::string text_of(T value) {
  constexpr std::size_t size = iecoop::max_text_length<T>;
  static_assert(size > 0, "no max_text_length for this type");
  using iecoop::to_text;  // an enumeration declared outside iecoop: ADL does not find them
  using iecoop::operator<<;
  const auto buffer = std::make_unique<char[]>(size);
  const char* end = to_text(buffer.get(), value);
  require(end > buffer.get() && end <= buffer.get() + size, "to_text writes 1..max_text_length characters");
  std::string text(buffer.get(), static_cast<std::size_t>(end - buffer.get()));
  std::ostringstream stream;
  stream << value;
  require(stream.str() == text, "operator<< writes what to_text writes", stream.str());
  // fmt writes a REAL as fmt's own shortest text (54344970, not 5.434497e+07), read back below.
  if constexpr (!iecoop::AnyReal<T>) {
    require(fmt::format("{}", value) == text, "fmt writes what to_text writes", fmt::format("{}", value));
  }
  if constexpr (!iecoop::Enumeration<T> || iecoop::enum_to_string<T>) {  // else TO_STRING gives the number
    const auto string = iecoop::convert<iecoop::STRING<size>>(value);
    require(string.view() == text, "convert<STRING> gives what to_text writes", string.view());
  }
  return text;
}

/// A parse result's error and position are consistent: an error other than none, at a position
/// within the text (the text's end at most).
template <class R>
void require_error_in_text(const R& result, std::string_view text) {
  if (result) return;
  require(static_cast<int>(result.error()) != 0, "a failed parse names its error", text);
  require(result.position() <= text.size(), "a parse error lies within the text", text);
}

}  // namespace iecoop_fuzz
