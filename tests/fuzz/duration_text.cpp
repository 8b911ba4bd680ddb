// Fuzz target: TIME and LTIME text (parse_time, parse_ltime, to_text). Checks, for any input:
//   - a failed parse names its error at a position within the text;
//   - what parses has a text of at most max_text_length<T> characters (written into a buffer of
//     exactly that size: T#11d23h59m59s999ms once overflowed one), printed alike by to_text,
//     operator<<, fmt and TO_STRING, which parses back to the same value;
//   - STRING_TO_TIME / STRING_TO_LTIME read what parse_time / parse_ltime read;
//   - a TIME literal is an LTIME literal of the same duration, and an LTIME literal written T# is
//     a TIME literal where it is whole milliseconds within TIME's range (else the errors agree);
//   - for a literal rejected for its lower unit overflowing (T#5m68s), the "..."_iec diagnostic
//     proposes a valid literal of the same duration (T#6m8s), or gives the literal's other error;
//   - the input's first 4 and 8 bytes, as a TIME and an LTIME, format and parse back.
#include "fuzz_check.hpp"

#include <cstddef>
#include <cstdint>
#include <limits>
#include <string>
#include <string_view>
#include <type_traits>

namespace {

using namespace iecoop;
using iecoop_fuzz::require;

template <class T>
parse_result<T> parse_duration(std::string_view text) {
  if constexpr (std::is_same_v<T, TIME>) {
    return parse_time(text);
  } else {
    return parse_ltime(text);
  }
}

template <class T>
void check_value(T value) {
  const std::string text = iecoop_fuzz::text_of(value);
  const auto back = parse_duration<T>(text);
  require(back.has_value() && back.value_or(T{}) == value, "a duration's text parses back to it", text);
}

template <class T>
void check_text(std::string_view text) {
  const auto parsed = parse_duration<T>(text);
  iecoop_fuzz::require_error_in_text(parsed, text);
  if (!parsed) return;
  const T value = parsed.value_or(T{});
  check_value(value);
  // A STRING ends at its first NUL and holds 80 characters; what parses has no spaces to trim.
  if (text.size() <= 80 && text.find('\0') == std::string_view::npos) {
    require(convert<T>(STRING<80>(text)) == value, "STRING_TO_<duration> reads what parse reads", text);
  }
}

/// The text's prefix is T# or TIME#.
bool written_as_time(std::string_view text) {
  const std::size_t hash = text.find('#');
  return hash != std::string_view::npos &&
         detail::classify_duration_prefix(text.substr(0, hash)) == detail::duration_prefix::time;
}

void check_time_against_ltime(std::string_view text) {
  const auto time = parse_time(text);
  const auto ltime = parse_ltime(text);
  if (time) {
    require(ltime.has_value() && ltime.value_or(LTIME{}) == convert<LTIME>(time.value_or(TIME{})),
            "a TIME literal is an LTIME literal of the same duration", text);
    return;
  }
  if (ltime && written_as_time(text)) {
    const std::uint64_t ns = ltime.value_or(LTIME{}).count();
    const bool fits = ns % 1'000'000 == 0 && ns / 1'000'000 <= std::numeric_limits<TIME::rep>::max();
    require(!fits, "an LTIME literal written T#, whole ms within TIME's range, is a TIME literal", text);
  }
  // Other than for the resolution, the range or the prefix, TIME rejects a text as LTIME does.
  if (time.error() != parse_error::too_precise && time.error() != parse_error::out_of_range &&
      time.error() != parse_error::wrong_prefix) {
    require(!ltime && ltime.error() == time.error() && ltime.position() == time.position(),
            "TIME and LTIME reject a text alike", text);
  }
}

/// "T#5m68s"_iec does not compile, and its message proposes the same duration spelt validly
/// (detail::normalized_duration): a value whose text is a valid literal, the duration the literal
/// means read with every unit allowed to overflow. Where the literal is wrong besides ("T#5m68s1x",
/// or beyond the type), the message gives that error instead.
template <class T>
void check_unit_overflow(std::string_view text) {
  const auto strict = parse_duration<T>(text);
  if (strict || strict.error() != parse_error::unit_overflow) return;
  const auto normalized = detail::normalized_duration<T>(text);
  iecoop_fuzz::require_error_in_text(normalized, text);
  if (!normalized) {
    require(normalized.error() != parse_error::unit_overflow, "a literal is wrong besides a unit overflowing", text);
    return;
  }
  constexpr bool is_time = std::is_same_v<T, TIME>;
  constexpr std::uint64_t resolution = is_time ? 1'000'000 : 1;
  const auto lenient = detail::parse_duration_ns(text, !is_time, resolution, true);
  const T value = normalized.value_or(T{});
  require(lenient.has_value() && lenient.value_or(0) == std::uint64_t{value.count()} * resolution,
          "the spelling proposed for a unit overflow is the same duration", text);
  check_value(value);
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string_view text = iecoop_fuzz::as_text(data, size);
  check_text<TIME>(text);
  check_text<LTIME>(text);
  check_time_against_ltime(text);
  check_unit_overflow<TIME>(text);
  check_unit_overflow<LTIME>(text);
  check_value(TIME::from_ticks(iecoop_fuzz::load<std::uint32_t>(data, size)));
  check_value(LTIME::from_ticks(iecoop_fuzz::load<std::uint64_t>(data, size)));
  return 0;
}
