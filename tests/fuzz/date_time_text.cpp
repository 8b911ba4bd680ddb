// Fuzz target: DATE, TOD, DT and their L forms as text (parse_time_point, to_text). Checks, for
// any input:
//   - a failed parse names its error at a position within the text;
//   - what parses has a text of at most max_text_length<T> characters, printed alike by to_text,
//     operator<<, fmt and TO_STRING, which parses back to the same value;
//   - STRING_TO_<T> reads what parse reads;
//   - a DATE, TOD or DT literal is an LDATE, LTOD or LDT literal of the same point;
//   - the input's first 4 and 8 bytes as a value of each type: its text (at most
//     max_text_length<T>) parses back to it, a DATE's or LDATE's to the midnight of its day; a
//     TOD or LTOD past midnight (as arithmetic leaves one) writes its hours past 23, which
//     parsing rejects as no time of day.
#include "fuzz_check.hpp"

#include <cstddef>
#include <cstdint>
#include <string>
#include <string_view>

namespace {

using namespace iecoop;
using iecoop_fuzz::require;

template <class T>
constexpr std::uint64_t ticks_per_day = detail::ns_per_day / detail::ns_per_tick<T>;

template <class T>
void check_value(T value) {
  const std::string text = iecoop_fuzz::text_of(value);
  const auto back = parse_time_point<T>(text);
  const std::uint64_t ticks = value.count();
  if constexpr (T::kind == time_point_kind::date) {
    const auto midnight = T::from_ticks(static_cast<typename T::rep>(ticks - ticks % ticks_per_day<T>));
    require(back.has_value() && back.value_or(T{}) == midnight, "a date's text parses back to its day", text);
  } else if (T::kind == time_point_kind::time_of_day && ticks >= ticks_per_day<T>) {
    require(!back && back.error() == parse_error::invalid_time_of_day,
            "a time of day past midnight writes an hour that parsing rejects", text);
  } else {
    require(back.has_value() && back.value_or(T{}) == value, "a point's text parses back to it", text);
  }
}

template <class T>
void check_text(std::string_view text) {
  const auto parsed = parse_time_point<T>(text);
  iecoop_fuzz::require_error_in_text(parsed, text);
  if (!parsed) return;
  const T value = parsed.value_or(T{});
  require(T::kind != time_point_kind::time_of_day || value.count() < ticks_per_day<T>,
          "a parsed time of day lies before midnight", text);
  check_value(value);
  // A STRING ends at its first NUL and holds 80 characters; what parses has no spaces to trim.
  if (text.size() <= 80 && text.find('\0') == std::string_view::npos) {
    require(convert<T>(STRING<80>(text)) == value, "STRING_TO_<point> reads what parse reads", text);
  }
}

/// A literal of the 32-bit form is one of the L form: the same point.
template <class Short, class Long>
void check_widening(std::string_view text) {
  const auto narrow = parse_time_point<Short>(text);
  if (!narrow) return;
  const auto wide = parse_time_point<Long>(text);
  require(wide.has_value() && wide.value_or(Long{}) == convert<Long>(narrow.value_or(Short{})),
          "a 32-bit point's literal is its L form's literal of the same point", text);
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string_view text = iecoop_fuzz::as_text(data, size);
  check_text<DATE>(text);
  check_text<TOD>(text);
  check_text<DT>(text);
  check_text<LDATE>(text);
  check_text<LTOD>(text);
  check_text<LDT>(text);
  check_widening<DATE, LDATE>(text);
  check_widening<TOD, LTOD>(text);
  check_widening<DT, LDT>(text);
  const auto bits = iecoop_fuzz::load<std::uint64_t>(data, size);
  check_value(DATE::from_ticks(static_cast<std::uint32_t>(bits)));
  check_value(TOD::from_ticks(static_cast<std::uint32_t>(bits)));
  check_value(DT::from_ticks(static_cast<std::uint32_t>(bits)));
  check_value(LDATE::from_ticks(bits));
  check_value(LTOD::from_ticks(bits));
  check_value(LDT::from_ticks(bits));
  // Small values too: the input's first 4 bytes as a 64-bit point's ticks.
  check_value(LTOD::from_ticks(static_cast<std::uint32_t>(bits)));
  check_value(LDT::from_ticks(static_cast<std::uint32_t>(bits) * std::uint64_t{1'000'000'000}));
  return 0;
}
