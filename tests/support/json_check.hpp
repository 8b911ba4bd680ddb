// A strict check of JSON text (RFC 8259) for the tests of what iecoop publishes: one value,
// whitespace around it, strings of well-formed UTF-8 (RFC 3629) whose escapes are the eight
// of the RFC and \uXXXX (a surrogate only as a pair), numbers in the RFC's grammar, no
// trailing commas, nesting within a limit. Written here for the tests (no JSON library is a
// dependency); the MQTT tests also hand the messages to Python's json module.
#pragma once

#include <cstddef>
#include <string_view>

namespace iecoop_test {

class json_checker {
 public:
  /// TRUE if `text` is one JSON value; where() tells where the first error is.
  bool check(std::string_view text) {
    text_ = text;
    at_ = 0;
    depth_ = 0;
    skip_space();
    if (!value()) return false;
    skip_space();
    return at_ == text_.size();
  }
  [[nodiscard]] std::size_t where() const { return at_; }

 private:
  static constexpr int max_depth = 64;

  [[nodiscard]] bool more() const { return at_ < text_.size(); }
  [[nodiscard]] unsigned char peek() const { return static_cast<unsigned char>(text_[at_]); }
  void skip_space() {
    while (more() && (peek() == ' ' || peek() == '\t' || peek() == '\n' || peek() == '\r')) ++at_;
  }
  bool literal(std::string_view word) {
    if (text_.substr(at_, word.size()) != word) return false;
    at_ += word.size();
    return true;
  }
  bool value() {
    if (!more()) return false;
    switch (peek()) {
      case '{': return object();
      case '[': return array();
      case '"': return string();
      case 't': return literal("true");
      case 'f': return literal("false");
      case 'n': return literal("null");
      default: return number();
    }
  }
  bool object() {
    if (++depth_ > max_depth) return false;
    ++at_;
    skip_space();
    if (more() && peek() == '}') {
      ++at_;
      --depth_;
      return true;
    }
    for (;;) {
      skip_space();
      if (!more() || peek() != '"' || !string()) return false;
      skip_space();
      if (!more() || peek() != ':') return false;
      ++at_;
      skip_space();
      if (!value()) return false;
      skip_space();
      if (!more()) return false;
      if (peek() == '}') {
        ++at_;
        --depth_;
        return true;
      }
      if (peek() != ',') return false;
      ++at_;
    }
  }
  bool array() {
    if (++depth_ > max_depth) return false;
    ++at_;
    skip_space();
    if (more() && peek() == ']') {
      ++at_;
      --depth_;
      return true;
    }
    for (;;) {
      skip_space();
      if (!value()) return false;
      skip_space();
      if (!more()) return false;
      if (peek() == ']') {
        ++at_;
        --depth_;
        return true;
      }
      if (peek() != ',') return false;
      ++at_;
    }
  }
  bool digits() {
    const std::size_t start = at_;
    while (more() && peek() >= '0' && peek() <= '9') ++at_;
    return at_ > start;
  }
  bool number() {
    if (more() && peek() == '-') ++at_;
    if (!more()) return false;
    if (peek() == '0') {
      ++at_;
    } else if (!digits()) {
      return false;
    }
    if (more() && peek() == '.') {
      ++at_;
      if (!digits()) return false;
    }
    if (more() && (peek() == 'e' || peek() == 'E')) {
      ++at_;
      if (more() && (peek() == '+' || peek() == '-')) ++at_;
      if (!digits()) return false;
    }
    return true;
  }
  /// Four hex digits after \u: their value, or -1.
  long hex4() {
    if (text_.size() - at_ < 4) return -1;
    long v = 0;
    for (int k = 0; k < 4; ++k) {
      const unsigned char c = peek();
      int d = -1;
      if (c >= '0' && c <= '9') d = c - '0';
      if (c >= 'a' && c <= 'f') d = c - 'a' + 10;
      if (c >= 'A' && c <= 'F') d = c - 'A' + 10;
      if (d < 0) return -1;
      v = v * 16 + d;
      ++at_;
    }
    return v;
  }
  /// One well-formed UTF-8 sequence of two or more bytes.
  bool utf8() {
    const unsigned char b0 = peek();
    const auto cont = [&](std::size_t k, unsigned lo, unsigned hi) {
      if (at_ + k >= text_.size()) return false;
      const auto b = static_cast<unsigned char>(text_[at_ + k]);
      return b >= lo && b <= hi;
    };
    std::size_t n = 0;
    if (b0 >= 0xC2 && b0 <= 0xDF)
      n = cont(1, 0x80, 0xBF) ? 2 : 0;
    else if (b0 == 0xE0)
      n = cont(1, 0xA0, 0xBF) && cont(2, 0x80, 0xBF) ? 3 : 0;
    else if ((b0 >= 0xE1 && b0 <= 0xEC) || b0 == 0xEE || b0 == 0xEF)
      n = cont(1, 0x80, 0xBF) && cont(2, 0x80, 0xBF) ? 3 : 0;
    else if (b0 == 0xED)
      n = cont(1, 0x80, 0x9F) && cont(2, 0x80, 0xBF) ? 3 : 0;
    else if (b0 == 0xF0)
      n = cont(1, 0x90, 0xBF) && cont(2, 0x80, 0xBF) && cont(3, 0x80, 0xBF) ? 4 : 0;
    else if (b0 >= 0xF1 && b0 <= 0xF3)
      n = cont(1, 0x80, 0xBF) && cont(2, 0x80, 0xBF) && cont(3, 0x80, 0xBF) ? 4 : 0;
    else if (b0 == 0xF4)
      n = cont(1, 0x80, 0x8F) && cont(2, 0x80, 0xBF) && cont(3, 0x80, 0xBF) ? 4 : 0;
    at_ += n;
    return n != 0;
  }
  bool string() {
    ++at_;  // the opening quote
    while (more()) {
      const unsigned char c = peek();
      if (c == '"') {
        ++at_;
        return true;
      }
      if (c < 0x20) return false;
      if (c >= 0x80) {
        if (!utf8()) return false;
        continue;
      }
      ++at_;
      if (c != '\\') continue;
      if (!more()) return false;
      const unsigned char e = peek();
      ++at_;
      if (e == '"' || e == '\\' || e == '/' || e == 'b' || e == 'f' || e == 'n' || e == 'r' || e == 't') continue;
      if (e != 'u') return false;
      const long u = hex4();
      if (u < 0) return false;
      if (u >= 0xDC00 && u <= 0xDFFF) return false;  // a low surrogate alone
      if (u >= 0xD800 && u <= 0xDBFF) {              // a high surrogate: its low one must follow
        if (!literal("\\u")) return false;
        const long low = hex4();
        if (low < 0xDC00 || low > 0xDFFF) return false;
      }
    }
    return false;  // no closing quote
  }

  std::string_view text_;
  std::size_t at_ = 0;
  int depth_ = 0;
};

/// TRUE if `text` is valid JSON (json_checker).
inline bool is_json(std::string_view text) { return json_checker{}.check(text); }

}  // namespace iecoop_test
