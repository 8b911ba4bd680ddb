// SPDX-License-Identifier: MIT
// iecoop/trace/detail/svg_writer.hpp — the SVG writer's text: buffered on the stack and handed to
// the caller's put() in pieces, XML-escaped, numbers without allocation, and the estimate of
// a text's width the layout goes by.
// IWYU pragma: private, include <iecoop/trace/svg.hpp>
#pragma once

#include <charconv>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <string_view>

#include <iecoop/config.hpp>
#include <iecoop/trace/channels.hpp>

#include <iecoop/detail/push_macros.hpp>

namespace iecoop::detail::svg {

/// Buffers the text on the stack and hands it to put() in pieces.
template <class Put>
class out {
 public:
  explicit out(Put& put) noexcept : put_(put) {}
  out(const out&) = delete;
  out& operator=(const out&) = delete;
  ~out() { flush(); }

  void raw(std::string_view s) {
    if (s.size() > sizeof(buffer_) - size_) {
      flush();
      if (s.size() > sizeof(buffer_)) {
        put_(s);
        return;
      }
    }
    for (const char c : s) buffer_[size_++] = c;
  }
  void num(std::int64_t v) {
    char b[24];
    const auto r = std::to_chars(b, b + sizeof(b), v);
    raw(std::string_view(b, static_cast<std::size_t>(r.ptr - b)));
  }
  void unum(std::uint64_t v) {
    char b[24];
    const auto r = std::to_chars(b, b + sizeof(b), v);
    raw(std::string_view(b, static_cast<std::size_t>(r.ptr - b)));
  }
  /// A count of tenths as a decimal number: 125 -> "12.5", 120 -> "12".
  void tenths(std::int64_t t) {
    if (t < 0) {
      raw("-");
      t = -t;
    }
    num(t / 10);
    if (t % 10 != 0) {
      const char d[2] = {'.', static_cast<char>('0' + t % 10)};
      raw(std::string_view(d, 2));
    }
  }
  /// Text or an attribute value: XML's special characters escaped; control characters and
  /// bytes that are not UTF-8 (neither may stand in an XML document) written as '?'.
  void escaped(std::string_view s) {
    std::size_t i = 0;
    while (i < s.size()) {
      const auto c = static_cast<unsigned char>(s[i]);
      if (c < 0x80) {
        switch (c) {
          case '&': raw("&amp;"); break;
          case '<': raw("&lt;"); break;
          case '>': raw("&gt;"); break;
          case '"': raw("&quot;"); break;
          case '\'': raw("&apos;"); break;
          default: raw(c < 0x20 || c == 0x7F ? std::string_view("?") : s.substr(i, 1)); break;
        }
        ++i;
        continue;
      }
      const std::size_t n = utf8_sequence(s, i);
      raw(n == 0 ? std::string_view("?") : s.substr(i, n));
      i += n == 0 ? 1 : n;
    }
  }
  void flush() {
    if (size_ != 0) put_(std::string_view(buffer_, size_));
    size_ = 0;
  }

  /// The length of the well-formed UTF-8 sequence of an XML character at s[i], or 0.
  static constexpr std::size_t utf8_sequence(std::string_view s, std::size_t i) noexcept {
    const auto b0 = static_cast<unsigned char>(s[i]);
    std::size_t n = 0;
    unsigned lo = 0x80;
    unsigned hi = 0xBF;
    if (b0 >= 0xC2 && b0 <= 0xDF) {
      n = 2;
    } else if (b0 >= 0xE0 && b0 <= 0xEF) {
      n = 3;
      if (b0 == 0xE0) lo = 0xA0;  // not overlong
      if (b0 == 0xED) hi = 0x9F;  // not a surrogate
    } else if (b0 >= 0xF0 && b0 <= 0xF4) {
      n = 4;
      if (b0 == 0xF0) lo = 0x90;  // not overlong
      if (b0 == 0xF4) hi = 0x8F;  // at most U+10FFFF
    } else {
      return 0;
    }
    if (i + n > s.size()) return 0;
    for (std::size_t k = 1; k < n; ++k) {
      const unsigned b = static_cast<unsigned char>(s[i + k]);
      if (b < (k == 1 ? lo : 0x80U) || b > (k == 1 ? hi : 0xBFU)) return 0;
    }
    if (b0 == 0xEF && static_cast<unsigned char>(s[i + 1]) == 0xBF && static_cast<unsigned char>(s[i + 2]) >= 0xBE) {
      return 0;  // U+FFFE, U+FFFF: not XML characters
    }
    return n;
  }

 private:
  Put& put_;
  char buffer_[2048];
  std::size_t size_ = 0;
};

/// An estimate of the width of `s` in a sans-serif font of `font_px` (no font metrics here).
constexpr double text_px(std::string_view s, double font_px) noexcept {
  std::size_t chars = 0;
  for (const char c : s) chars += (static_cast<unsigned char>(c) & 0xC0U) != 0x80U ? 1U : 0U;
  return static_cast<double>(chars) * font_px * 0.64;
}
inline double name_px(const trace_channel& channel, double font_px) {
  double px = 0;
  put_channel_name(channel, [&](std::string_view s) { px += text_px(s, font_px); });
  return px;
}

inline std::int64_t to_int(double v) noexcept { return static_cast<std::int64_t>(std::floor(v)); }
inline std::int64_t to_tenths(double v) noexcept { return static_cast<std::int64_t>(std::floor(v * 10 + 0.5)); }

}  // namespace iecoop::detail::svg

#include <iecoop/detail/pop_macros.hpp>
