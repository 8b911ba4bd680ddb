// Fuzz target: number and BOOL text (parse_integer for every integer type, parse_real for REAL
// and LREAL, parse_bool, to_text). Checks, for any input:
//   - a failed parse names its error at a position within the text;
//   - what parses has a text of at most max_text_length<T> characters, printed alike by to_text,
//     operator<<, fmt and TO_STRING, which parses back to the same value (a REAL to the same bits);
//   - STRING_TO_<T> reads what parse reads;
//   - a decimal integer without a type prefix means one number whatever the type: each type
//     that takes it gives that number, and each type whose range holds it takes it (an unsigned
//     type reports a negative number as negative); without '_', '+' and '#' it is the number
//     std::from_chars reads;
//   - a based integer (16#FF) is a bit pattern: each unsigned type that takes it gives the same
//     pattern, and so does the signed type of each width, reinterpreted;
//   - parse_bool takes TRUE, FALSE, 1 and 0 (any case, optionally BOOL#) and nothing else;
//   - the input's first bytes as a value of each integer type, REAL and LREAL format and parse
//     back (a NaN or infinity only formats).
#include "fuzz_check.hpp"

#include <charconv>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <limits>
#include <optional>
#include <string>
#include <string_view>
#include <system_error>
#include <type_traits>

namespace {

using namespace iecoop;
using iecoop_fuzz::require;

/// A STRING ends at its first NUL and holds 80 characters; what parses has no spaces to trim.
bool fits_string(std::string_view text) { return text.size() <= 80 && text.find('\0') == std::string_view::npos; }

// --- Integers ----------------------------------------------------------------------------

/// A number of any integer type, as sign and magnitude.
struct number {
  bool negative = false;
  std::uint64_t magnitude = 0;
  friend bool operator==(const number&, const number&) = default;
};

template <class T>
number number_of(T value) {
  const auto v = value.value();
  if constexpr (std::is_signed_v<typename T::rep>) {
    if (v < 0) return {true, std::uint64_t{0} - static_cast<std::uint64_t>(static_cast<std::int64_t>(v))};
  }
  return {false, static_cast<std::uint64_t>(v)};
}

template <class T>
bool in_range(number n) {
  using rep = typename T::rep;
  if (n.magnitude == 0) return true;
  if (!n.negative) return n.magnitude <= static_cast<std::uint64_t>(std::numeric_limits<rep>::max());
  if constexpr (std::is_unsigned_v<rep>) {
    return false;
  } else {
    return n.magnitude <= static_cast<std::uint64_t>(std::numeric_limits<rep>::max()) + 1;
  }
}

template <class T>
void check_integer_value(T value) {
  const std::string text = iecoop_fuzz::text_of(value);
  const auto back = parse_integer<T>(text);
  require(back.has_value() && back.value_or(T{}) == value, "an integer's text parses back to it", text);
}

/// What the integer types made of one text, for the checks across types.
struct integer_readings {
  std::optional<number> decimal;  // the number a type without range limits would read
  bool any_failed_in_range = false;
};

template <class T>
void check_integer_text(std::string_view text, bool decimal_unprefixed, integer_readings& readings) {
  const auto parsed = parse_integer<T>(text);
  iecoop_fuzz::require_error_in_text(parsed, text);
  if (parsed) {
    const T value = parsed.value_or(T{});
    check_integer_value(value);
    if (fits_string(text)) require(convert<T>(STRING<80>(text)) == value, "STRING_TO_<integer> reads parse's", text);
    if (decimal_unprefixed) {
      const number n = number_of(value);
      require(!readings.decimal || *readings.decimal == n, "a decimal text is one number in every type", text);
      readings.decimal = n;
    }
  } else if (decimal_unprefixed &&
             (parsed.error() == parse_error::out_of_range || parsed.error() == parse_error::negative)) {
    // Out of T's range: every type whose range holds the number must take it (checked below).
  } else if (decimal_unprefixed) {
    readings.any_failed_in_range = true;  // a syntax error: no type may take the text
  }
}

template <class T>
void check_integer_range(std::string_view text, const integer_readings& readings) {
  if (!readings.decimal) return;
  const auto parsed = parse_integer<T>(text);
  require(parsed.has_value() == in_range<T>(*readings.decimal), "a type takes a decimal number iff in its range", text);
  if (!parsed && readings.decimal->negative && std::is_unsigned_v<typename T::rep>) {
    require(parsed.error() == parse_error::negative, "an unsigned type reports a negative number as such", text);
  }
}

/// Based literals: a bit pattern in any type of the width.
template <class U, class S>
void check_based_pattern(std::string_view text) {
  const auto u = parse_integer<U>(text);
  const auto s = parse_integer<S>(text);
  require(u.has_value() == s.has_value(), "a based literal fits a signed and an unsigned type alike", text);
  if (u) {
    using urep = typename U::rep;
    require(static_cast<urep>(s.value_or(S{}).value()) == u.value_or(U{}).value(),
            "a based literal is the same bit pattern in a signed and an unsigned type", text);
  }
}

/// The text is a number to std::from_chars: an optional '-', then decimal digits only.
template <class T>
void check_against_from_chars(std::string_view text) {
  using rep = typename T::rep;
  const std::size_t digits_at = !text.empty() && text.front() == '-' ? 1 : 0;
  if (text.size() == digits_at) return;
  for (std::size_t i = digits_at; i < text.size(); ++i) {
    if (text[i] < '0' || text[i] > '9') return;
  }
  rep expected{};
  const auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), expected);
  const auto parsed = parse_integer<T>(text);
  if (std::is_unsigned_v<rep> && digits_at == 1) {
    return;  // from_chars takes no '-' for an unsigned type; parse_integer takes -0
  }
  if (ec == std::errc{} && end == text.data() + text.size()) {
    require(parsed.has_value() && parsed.value_or(T{}).value() == expected, "parse_integer reads what from_chars reads",
            text);
  } else {
    require(!parsed, "parse_integer rejects what from_chars cannot read", text);
  }
}

void check_integers(std::string_view text, const std::uint8_t* data, std::size_t size) {
  // Decimal and without a type prefix: no '#' at all.
  const bool decimal_unprefixed = text.find('#') == std::string_view::npos;
  integer_readings readings;
  check_integer_text<SINT>(text, decimal_unprefixed, readings);
  check_integer_text<INT>(text, decimal_unprefixed, readings);
  check_integer_text<DINT>(text, decimal_unprefixed, readings);
  check_integer_text<LINT>(text, decimal_unprefixed, readings);
  check_integer_text<USINT>(text, decimal_unprefixed, readings);
  check_integer_text<UINT>(text, decimal_unprefixed, readings);
  check_integer_text<UDINT>(text, decimal_unprefixed, readings);
  check_integer_text<ULINT>(text, decimal_unprefixed, readings);
  check_integer_text<BYTE>(text, decimal_unprefixed, readings);
  check_integer_text<WORD>(text, decimal_unprefixed, readings);
  check_integer_text<DWORD>(text, decimal_unprefixed, readings);
  check_integer_text<LWORD>(text, decimal_unprefixed, readings);
  if (decimal_unprefixed) {
    require(!(readings.decimal && readings.any_failed_in_range), "a decimal text is valid in all types or none", text);
    check_integer_range<SINT>(text, readings);
    check_integer_range<INT>(text, readings);
    check_integer_range<DINT>(text, readings);
    check_integer_range<LINT>(text, readings);
    check_integer_range<USINT>(text, readings);
    check_integer_range<UINT>(text, readings);
    check_integer_range<UDINT>(text, readings);
    check_integer_range<ULINT>(text, readings);
    check_integer_range<BYTE>(text, readings);
    check_integer_range<WORD>(text, readings);
    check_integer_range<DWORD>(text, readings);
    check_integer_range<LWORD>(text, readings);
    check_against_from_chars<SINT>(text);
    check_against_from_chars<INT>(text);
    check_against_from_chars<DINT>(text);
    check_against_from_chars<LINT>(text);
    check_against_from_chars<USINT>(text);
    check_against_from_chars<UINT>(text);
    check_against_from_chars<UDINT>(text);
    check_against_from_chars<ULINT>(text);
  } else if (text.find('#') == text.find_first_not_of("0123456789") && !text.starts_with("10#")) {
    // A base other than 10, without a type prefix (16#FF, 2#1010).
    check_based_pattern<USINT, SINT>(text);
    check_based_pattern<UINT, INT>(text);
    check_based_pattern<UDINT, DINT>(text);
    check_based_pattern<ULINT, LINT>(text);
  }
  const auto bits = iecoop_fuzz::load<std::uint64_t>(data, size);
  check_integer_value(SINT(static_cast<std::int8_t>(bits)));
  check_integer_value(INT(static_cast<std::int16_t>(bits)));
  check_integer_value(DINT(static_cast<std::int32_t>(bits)));
  check_integer_value(LINT(static_cast<std::int64_t>(bits)));
  check_integer_value(USINT(static_cast<std::uint8_t>(bits)));
  check_integer_value(UINT(static_cast<std::uint16_t>(bits)));
  check_integer_value(UDINT(static_cast<std::uint32_t>(bits)));
  check_integer_value(ULINT(bits));
  check_integer_value(BYTE(static_cast<std::uint8_t>(bits)));
  check_integer_value(WORD(static_cast<std::uint16_t>(bits)));
  check_integer_value(DWORD(static_cast<std::uint32_t>(bits)));
  check_integer_value(LWORD(bits));
}

// --- REAL, LREAL -------------------------------------------------------------------------

template <class T>
bool same_bits(T a, T b) {
  const auto x = a.value();
  const auto y = b.value();
  return std::memcmp(&x, &y, sizeof x) == 0;
}

template <class T>
void check_real_value(T value) {
  const std::string text = iecoop_fuzz::text_of(value);
  if (!std::isfinite(value.value())) return;  // "nan", "inf": no IEC literal
  const auto back = parse_real<T>(text);
  require(back.has_value() && same_bits(back.value_or(T{}), value), "a REAL's text parses back to the same bits", text);
  const std::string formatted = fmt::format("{}", value);
  const auto back_from_fmt = parse_real<T>(formatted);
  require(back_from_fmt.has_value() && same_bits(back_from_fmt.value_or(T{}), value),
          "a REAL formatted by fmt parses back to the same bits", formatted);
}

template <class T>
void check_real_text(std::string_view text) {
  const auto parsed = parse_real<T>(text);
  iecoop_fuzz::require_error_in_text(parsed, text);
  if (!parsed) return;
  const T value = parsed.value_or(T{});
  require(std::isfinite(value.value()), "a REAL literal is finite", text);
  check_real_value(value);
  if (fits_string(text)) {
    require(same_bits(convert<T>(STRING<80>(text)), value), "STRING_TO_<REAL> reads what parse_real reads", text);
  }
}

// --- BOOL --------------------------------------------------------------------------------

void check_bool_text(std::string_view text) {
  const auto parsed = parse_bool(text);
  iecoop_fuzz::require_error_in_text(parsed, text);
  std::string_view body = text;
  const std::size_t hash = text.find('#');
  if (hash != std::string_view::npos && detail::iequals(text.substr(0, hash), "BOOL")) body = text.substr(hash + 1);
  const bool is_true = detail::iequals(body, "TRUE") || body == "1";
  const bool is_false = detail::iequals(body, "FALSE") || body == "0";
  require(parsed.has_value() == (is_true || is_false), "parse_bool takes TRUE, FALSE, 1, 0 and nothing else", text);
  if (!parsed) return;
  const BOOL value = parsed.value_or(FALSE);
  require(static_cast<bool>(value) == is_true, "parse_bool reads TRUE and 1 as TRUE", text);
  const std::string written = iecoop_fuzz::text_of(value);
  require(parse_bool(written).value_or(!value) == value, "a BOOL's text parses back to it", written);
  if (fits_string(text)) require(convert<BOOL>(STRING<80>(text)) == value, "STRING_TO_BOOL reads parse_bool's", text);
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string_view text = iecoop_fuzz::as_text(data, size);
  check_integers(text, data, size);
  check_real_text<REAL>(text);
  check_real_text<LREAL>(text);
  check_real_value(REAL(iecoop_fuzz::load<float>(data, size)));
  check_real_value(LREAL(iecoop_fuzz::load<double>(data, size)));
  check_bool_text(text);
  return 0;
}
