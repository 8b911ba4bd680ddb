// SPDX-License-Identifier: MIT
// iecoop/detail/utf8.hpp — UCS-2 (WSTRING) to UTF-8, for printing.
// IWYU pragma: private
#pragma once

namespace iecoop::detail {

/// The longest UTF-8 encoding of one UCS-2 code unit.
inline constexpr int utf8_max_per_unit = 3;

/// Writes the UTF-8 encoding of a UCS-2 code unit at `out` and returns the end; lone
/// surrogates (which UCS-2 cannot pair) are written as '?'.
constexpr char* put_utf8(char* out, char16_t c) noexcept {
  const auto u = static_cast<unsigned>(c);
  if (u < 0x80) {
    *out++ = static_cast<char>(u);
  } else if (u < 0x800) {
    *out++ = static_cast<char>(0xC0 | (u >> 6));
    *out++ = static_cast<char>(0x80 | (u & 0x3F));
  } else if (u >= 0xD800 && u <= 0xDFFF) {
    *out++ = '?';
  } else {
    *out++ = static_cast<char>(0xE0 | (u >> 12));
    *out++ = static_cast<char>(0x80 | ((u >> 6) & 0x3F));
    *out++ = static_cast<char>(0x80 | (u & 0x3F));
  }
  return out;
}

}  // namespace iecoop::detail
