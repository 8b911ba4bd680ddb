// Fuzz target: STRING and WSTRING text: assignment (truncation, a NUL ending the text, a view into
// the string itself), the string functions LEN LEFT RIGHT MID CONCAT INSERT DELETE REPLACE FIND
// with any lengths and positions, STRING <-> WSTRING, WSTRING printed as UTF-8, and STRING_TO_<T>
// on any text. iecoop has no parser of ST's quoted string literals ('abc$N'), so there is none to
// fuzz. Each result is checked against a model on std::string that follows the documented rules.
//
// Input: bytes 0..1 and 2..3 are a length L and a position P (int16, little-endian); the rest is
// two texts separated by the first '\n'.
#include "fuzz_check.hpp"

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <sstream>
#include <string>
#include <string_view>

namespace {

using namespace iecoop;
using iecoop_fuzz::require;

/// What STRING(N) holds after assigning `text`: the text up to its first NUL, at most N characters.
std::string held(std::string_view text, std::size_t n) {
  const std::size_t nul = text.find('\0');
  if (nul != std::string_view::npos) text = text.substr(0, nul);
  return std::string(text.substr(0, std::min(text.size(), n)));
}

// The model of each function (string_functions.hpp's rules), with 1-based positions.
std::string left_model(const std::string& s, std::int64_t l) {
  if (l <= 0) return {};
  return s.substr(0, static_cast<std::size_t>(std::min<std::int64_t>(l, static_cast<std::int64_t>(s.size()))));
}
std::string right_model(const std::string& s, std::int64_t l) {
  if (l <= 0) return {};
  const auto n = static_cast<std::size_t>(std::min<std::int64_t>(l, static_cast<std::int64_t>(s.size())));
  return s.substr(s.size() - n);
}
std::string mid_model(const std::string& s, std::int64_t l, std::int64_t p) {
  const auto size = static_cast<std::int64_t>(s.size());
  if (l <= 0 || p < 1 || p > size) return {};
  return s.substr(static_cast<std::size_t>(p - 1), static_cast<std::size_t>(std::min(l, size - (p - 1))));
}
std::string insert_model(const std::string& a, const std::string& b, std::int64_t p) {
  if (p < 0 || p > static_cast<std::int64_t>(a.size())) return a;
  const auto at = static_cast<std::size_t>(p);
  return a.substr(0, at) + b + a.substr(at);
}
std::string delete_model(const std::string& s, std::int64_t l, std::int64_t p) {
  const auto size = static_cast<std::int64_t>(s.size());
  if (l <= 0 || p < 1 || p > size) return s;
  const std::int64_t count = std::min(l, size - (p - 1));
  return s.substr(0, static_cast<std::size_t>(p - 1)) + s.substr(static_cast<std::size_t>(p - 1 + count));
}
std::string replace_model(const std::string& a, const std::string& b, std::int64_t l, std::int64_t p) {
  const auto size = static_cast<std::int64_t>(a.size());
  if (l < 0 || p < 1 || p > size + 1) return a;
  const std::int64_t count = std::min(l, size - (p - 1));
  return a.substr(0, static_cast<std::size_t>(p - 1)) + b + a.substr(static_cast<std::size_t>(p - 1 + count));
}
std::int64_t find_model(const std::string& a, const std::string& b) {
  if (b.empty()) return 0;
  const std::size_t at = a.find(b);
  return at == std::string::npos ? 0 : static_cast<std::int64_t>(at) + 1;
}

/// The functions on strings A and B with the length and position given as `l` and `p` (any
/// position argument), whose values are `lv` and `pv`.
template <class A, class B, class L, class P>
void check_functions(const A& a, const B& b, const L& l, const P& p, std::int64_t lv, std::int64_t pv) {
  const std::string am(a.view());
  const std::string bm(b.view());
  require(LEFT(a, l).view() == left_model(am, lv), "LEFT", am);
  require(RIGHT(a, l).view() == right_model(am, lv), "RIGHT", am);
  require(MID(a, l, p).view() == mid_model(am, lv, pv), "MID", am);
  require(INSERT(a, b, p).view() == insert_model(am, bm, pv), "INSERT", am);
  require(DELETE(a, l, p).view() == delete_model(am, lv, pv), "DELETE", am);
  require(REPLACE(a, b, l, p).view() == replace_model(am, bm, lv, pv), "REPLACE", am);
}

template <class A, class B>
void check_strings(const A& a, const B& b, std::int16_t l, std::int16_t p) {
  const std::string am(a.view());
  const std::string bm(b.view());
  require(LEN(a).value() == static_cast<std::int64_t>(am.size()), "LEN", am);
  require(CONCAT(a, b).view() == am + bm, "CONCAT of two", am);
  require(CONCAT(a, b, a).view() == am + bm + am, "CONCAT of three", am);
  require(FIND(a, b).value() == find_model(am, bm), "FIND", am);
  check_functions(a, b, INT(l), INT(p), l, p);
  check_functions(a, b, DINT(l) * 1000, DINT(p), std::int64_t{l} * 1000, p);
  check_functions(a, b, static_cast<int>(l), static_cast<long long>(p), l, p);
  // An unsigned argument beyond LINT's range (a negative number's bits) is beyond any string.
  constexpr std::int64_t huge = std::numeric_limits<std::int64_t>::max();
  const ULINT ul(static_cast<std::uint64_t>(std::int64_t{l}));
  const ULINT up(static_cast<std::uint64_t>(std::int64_t{p}));
  check_functions(a, b, ul, up, l < 0 ? huge : l, p < 0 ? huge : p);
}

/// A WSTRING as UTF-8 (operator<< and fmt), decoded: each unit, a surrogate as '?'.
template <std::size_t N>
void check_utf8(const WSTRING<N>& w) {
  std::ostringstream stream;
  stream << w;
  const std::string utf8 = stream.str();
  require(fmt::format("{}", w) == utf8, "fmt writes a WSTRING as operator<< does", utf8);
  std::u16string decoded;
  for (std::size_t i = 0; i < utf8.size();) {
    const auto b0 = static_cast<unsigned char>(utf8[i]);
    std::size_t n = b0 < 0x80 ? 1 : (b0 & 0xE0) == 0xC0 ? 2 : (b0 & 0xF0) == 0xE0 ? 3 : 0;
    require(n != 0 && i + n <= utf8.size(), "a WSTRING prints as valid UTF-8", utf8);
    char32_t c = n == 1 ? b0 : n == 2 ? (b0 & 0x1Fu) : (b0 & 0x0Fu);
    for (std::size_t k = 1; k < n; ++k) {
      const auto bk = static_cast<unsigned char>(utf8[i + k]);
      require((bk & 0xC0) == 0x80, "a WSTRING prints as valid UTF-8", utf8);
      c = (c << 6) | (bk & 0x3Fu);
    }
    const char32_t smallest[] = {0, 0, 0x80, 0x800};
    require(c >= smallest[n], "a WSTRING prints as shortest UTF-8", utf8);
    decoded += static_cast<char16_t>(c);
    i += n;
  }
  std::u16string expected(w.view());
  for (char16_t& c : expected) {
    if (c >= 0xD800 && c <= 0xDFFF) c = u'?';
  }
  require(decoded == expected, "a WSTRING prints as the UTF-8 of its characters", utf8);
}

void check_conversions(std::string_view text, std::string_view raw16) {
  const STRING<16> s(text);
  const auto w = convert<WSTRING<16>>(s);
  require(w.size() == s.size(), "STRING_TO_WSTRING keeps every character", text);
  for (std::size_t i = 0; i < s.size(); ++i) {
    require(w[i] == static_cast<char16_t>(static_cast<unsigned char>(s[i])), "STRING_TO_WSTRING is Latin-1", text);
  }
  require(convert<STRING<16>>(w) == s, "STRING_TO_WSTRING_TO_STRING is the identity", text);
  require(convert<STRING<4>>(w).view() == s.view().substr(0, std::min<std::size_t>(4, s.size())),
          "WSTRING_TO_STRING truncates", text);
  check_utf8(w);
  // Two bytes each, any UCS-2 unit: above 255 it becomes '?' in a STRING.
  std::u16string units;
  for (std::size_t i = 0; i + 1 < raw16.size(); i += 2) {
    units += static_cast<char16_t>(static_cast<unsigned char>(raw16[i]) |
                                   static_cast<unsigned>(static_cast<unsigned char>(raw16[i + 1])) << 8);
  }
  const WSTRING<10> wide(units);
  std::u16string wide_model = units.substr(0, std::min(units.find(u'\0'), std::size_t{10}));
  require(wide.view() == wide_model, "a WSTRING holds its text up to a NUL, 10 characters at most", raw16);
  const auto narrow = convert<STRING<10>>(wide);
  require(narrow.size() == wide.size(), "WSTRING_TO_STRING keeps every character", raw16);
  for (std::size_t i = 0; i < wide.size(); ++i) {
    const char16_t c = wide[i];
    require(static_cast<unsigned char>(narrow[i]) == (c <= 0xFF ? c : u'?'), "WSTRING_TO_STRING: '?' above 255", raw16);
  }
  check_utf8(wide);
}

/// STRING_TO_<T> on any text: a literal of T where the trimmed text is one, else (integers) a
/// REAL's text rounded half away from zero where it lies in T's range, else 0.
template <class T>
void check_to_integer(std::string_view text) {
  using rep = typename T::rep;
  const STRING<80> s(text);
  const std::string_view trimmed = detail::trim(s.view());
  const T result = convert<T>(s);
  const auto integer = parse_integer<T>(trimmed);
  if (integer) {
    require(result == integer.value_or(T{}), "STRING_TO_<integer> reads an integer literal", text);
    return;
  }
  const auto real = parse_real<LREAL>(trimmed);
  if (integer.error() == parse_error::out_of_range || !real) {
    require(result == T{}, "STRING_TO_<integer> of no number is 0", text);
    return;
  }
  const double x = real.value_or(LREAL{}).value();
  const double low = static_cast<double>(std::numeric_limits<rep>::min()) - 0.5;
  const double high = static_cast<double>(std::numeric_limits<rep>::max()) + 0.5;
  if (!(x > low && x < high)) {
    require(result == T{}, "STRING_TO_<integer> of a REAL out of range is 0", text);
    return;
  }
  require(result.value() == static_cast<rep>(std::round(x)), "STRING_TO_<integer> rounds a REAL's text", text);
}

void check_to_other(std::string_view text) {
  const STRING<80> s(text);
  const std::string_view trimmed = detail::trim(s.view());
  require(convert<BOOL>(s) == parse_bool(trimmed).value_or(FALSE), "STRING_TO_BOOL", text);
  require(convert<TIME>(s) == parse_time(trimmed).value_or(TIME{}), "STRING_TO_TIME", text);
  require(convert<LTIME>(s) == parse_ltime(trimmed).value_or(LTIME{}), "STRING_TO_LTIME", text);
  require(convert<DT>(s) == parse_dt(trimmed).value_or(DT{}), "STRING_TO_DT", text);
  require(convert<TOD>(s) == parse_tod(trimmed).value_or(TOD{}), "STRING_TO_TOD", text);
  const auto real = parse_real<REAL>(trimmed);
  const REAL converted = convert<REAL>(s);
  require(converted.value() == real.value_or(REAL{}).value(), "STRING_TO_REAL", text);
  // Through a WSTRING: the same.
  require(convert<DINT>(convert<WSTRING<80>>(s)) == convert<DINT>(s), "WSTRING_TO_DINT is STRING_TO_DINT", text);
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const auto l = iecoop_fuzz::load<std::int16_t>(data, size);
  const auto p = size > 2 ? iecoop_fuzz::load<std::int16_t>(data + 2, size - 2) : std::int16_t{0};
  const std::string_view rest = size > 4 ? iecoop_fuzz::as_text(data + 4, size - 4) : std::string_view{};
  const std::size_t split = rest.find('\n');
  const std::string_view first = rest.substr(0, split);
  const std::string_view second = split == std::string_view::npos ? std::string_view{} : rest.substr(split + 1);

  const STRING<16> a(first);
  const STRING<8> b(second);
  const STRING<255> long_a(first);
  require(a.view() == held(first, 16), "a STRING(16) holds its text up to a NUL, 16 characters at most", first);
  require(b.view() == held(second, 8), "a STRING(8) holds its text up to a NUL, 8 characters at most", second);
  require(long_a.view() == held(first, 255), "a STRING(255) holds its text up to a NUL", first);
  check_strings(a, b, l, p);
  check_strings(b, a, l, p);
  check_strings(long_a, b, l, p);
  check_strings(a, STRING<1>(), l, p);

  // Assigning a view into the string itself (documented as allowed).
  STRING<16> self = a;
  const std::size_t from = static_cast<std::uint16_t>(p) % (self.size() + 1);
  self.assign(self.view().substr(from));
  require(self.view() == a.view().substr(from), "assigning a view into the string itself", first);

  check_conversions(first, second);
  check_to_integer<SINT>(first);
  check_to_integer<DINT>(first);
  check_to_integer<UDINT>(first);
  check_to_other(first);
  return 0;
}
