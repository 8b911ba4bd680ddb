// IEC literal text: every duration literal form, valid and invalid, integer and BOOL
// literals, REAL text, and formatting back to IEC text.
#include "iecoop_test.hpp"

#include <fmt/format.h>

#include <iecoop/fmt.hpp>

#include <algorithm>
#include <cstdint>
#include <sstream>
#include <string>
#include <string_view>

using namespace iecoop;

namespace {

struct valid_duration {
  std::string_view text;
  std::uint64_t ns;
};

// Valid TIME literals (TC-TIMECONST, CDS-TIME) and their value in nanoseconds.
constexpr valid_duration valid_times[] = {
    {"T#1h2m3s4ms", 3723004000000},
    {"TIME#5s", 5000000000},
    {"t#1.5s", 1500000000},
    {"T#100s12ms", 100012000000},  // the highest unit may overflow
    {"time#12ms", 12000000},
    {"T#0ms", 0},
    {"T#0s", 0},
    {"T#2.5h", 9000000000000},
    {"T#1d", 86400000000000},
    {"T#5d14h12m18s3ms", 483138003000000},
    {"T#3m0.5s", 180500000000},  // a fraction in the last unit
    {"T#1h_30m", 5400000000000},
    {"T#1_000ms", 1000000000},
    {"T#1D2H3M4S5MS", 93784005000000},         // units in upper case
    {"T#49d17h2m47s295ms", 4294967295000000},  // the largest TIME
    {"T#0.001s", 1000000},
    {"T#2000us", 2000000},  // whole milliseconds, written in us
};

struct invalid_literal {
  std::string_view text;
  parse_error error;
  std::size_t position;
};

constexpr invalid_literal invalid_times[] = {
    {"", parse_error::empty, 0},
    {"15ms", parse_error::missing_prefix, 0},  // "15ms without prefix: error"
    {"LTIME#5s", parse_error::wrong_prefix, 0},
    {"D#5s", parse_error::wrong_prefix, 0},
    {"T#", parse_error::no_value, 2},
    {"t#5m68s", parse_error::unit_overflow, 4},  // "t#5m68s: error"
    {"T#1h60m", parse_error::unit_overflow, 4},
    {"T#1d24h", parse_error::unit_overflow, 4},
    {"T#1s1000ms", parse_error::unit_overflow, 4},
    {"t#4ms13d", parse_error::unit_order, 7},  // "t#4ms13d: error"
    {"T#1s2s", parse_error::unit_order, 5},
    {"T#1m1h", parse_error::unit_order, 5},
    {"T#5", parse_error::missing_unit, 3},
    {"T#1.5", parse_error::missing_unit, 5},
    {"T#5x", parse_error::unknown_unit, 3},
    {"T#5sec", parse_error::unknown_unit, 3},
    {"T#1.5s2ms", parse_error::fraction_not_last, 6},
    {"T#1.5ms", parse_error::too_precise, 2},  // TIME resolves 1 ms
    {"T#1500us", parse_error::too_precise, 2},
    {"T#1ns", parse_error::too_precise, 2},
    {"T#49d17h2m47s296ms", parse_error::out_of_range, 2},
    {"T#50d", parse_error::out_of_range, 2},
    {"T#99999999999999999999d", parse_error::out_of_range, 2},
    {"T#-5s", parse_error::negative, 2},
    {"T#_1s", parse_error::misplaced_underscore, 2},
    {"T#1s_", parse_error::misplaced_underscore, 4},
    {"T#1__0s", parse_error::misplaced_underscore, 3},
    {"T#1._5s", parse_error::misplaced_underscore, 4},
    {"T#1h 2m", parse_error::expected_digit, 4},
    {"T#5d14h12m18s3.5ms", parse_error::too_precise, 13},  // IEC's example needs LTIME here
    {"T#.5s", parse_error::expected_digit, 2},
};

}  // namespace

TEST_SUITE("IEC literal text") {
  TEST_CASE("every valid TIME literal form parses to its value") {
    for (const auto& literal : valid_times) {
      CAPTURE(literal.text);
      const auto result = parse_time(literal.text);
      REQUIRE(result.has_value());
      CHECK(result.value().count() * std::uint64_t{1000000} == literal.ns);
      CHECK(result.position() == 0u);
    }
  }

  TEST_CASE("every invalid TIME literal is rejected with its reason and position") {
    for (const auto& literal : invalid_times) {
      CAPTURE(literal.text);
      const auto result = parse_time(literal.text);
      CHECK_FALSE(result.has_value());
      CHECK_FALSE(static_cast<bool>(result));
      CHECK(result.error() == literal.error);
      CHECK(result.position() == literal.position);
      CHECK(std::string_view(describe(result.error())).size() > 5);
    }
  }

  TEST_CASE("LTIME literals resolve nanoseconds and accept TIME literals") {
    CHECK(parse_ltime("LTIME#1ms500us").value_or({}).count() == 1500000u);
    CHECK(parse_ltime("LT#5s").value_or({}).count() == 5000000000u);
    CHECK(parse_ltime("ltime#1000d15h23m12s34ms2us44ns").value_or({}).count() == 86455392034002044u);
    CHECK(parse_ltime("LTIME#1.5us").value_or({}).count() == 1500u);
    CHECK(parse_ltime("LTIME#5d14h12m18s3.5ms").value_or({}).count() == 483138003500000u);
    CHECK(parse_ltime("LTIME#0.000000001s").value_or({}).count() == 1u);
    CHECK(parse_ltime("T#1.5s").value_or({}).count() == 1500000000u);  // a TIME value widens
    CHECK(parse_ltime("LTIME#213503d23h34m33s709ms551us615ns").value_or({}) == LTIME::max());
    CHECK(parse_ltime("LTIME#213503d23h34m33s709ms551us616ns").error() == parse_error::out_of_range);
    CHECK(parse_ltime("LTIME#0.5ns").error() == parse_error::too_precise);
    CHECK(parse_ltime("LTIME#1us1000ns").error() == parse_error::unit_overflow);
    CHECK(parse_ltime("LTIME#1ns1us").error() == parse_error::unit_order);
  }

  TEST_CASE("value() of a failed parse reports a fault and returns zero") {
    iecoop_test::fault_recorder faults;
    CHECK(parse_time("t#5m68s").value() == TIME());
    CHECK(faults.count == 1);
    CHECK(faults.last_kind == fault_kind::invalid_value);
    CHECK(parse_time("T#5s").value_or(TIME(7)) == TIME(5000));
    CHECK(parse_time("nonsense").value_or(TIME(7)) == TIME(7));
    CHECK(*parse_time("T#1s") == TIME(1000));
  }

  TEST_CASE("integer literals: bases, underscores, signs and type prefixes") {
    CHECK(parse_integer<INT>("42").value_or(0) == 42);
    CHECK(parse_integer<INT>("-32768").value_or(0) == -32768);
    CHECK(parse_integer<INT>("+7").value_or(0) == 7);
    CHECK(parse_integer<DINT>("1_000_000").value_or(0) == 1000000);
    CHECK(parse_integer<BYTE>("2#1001_0011").value_or(0) == 0x93);
    CHECK(parse_integer<WORD>("8#67").value_or(0) == 55);
    CHECK(parse_integer<WORD>("16#A").value_or(0) == 10);
    CHECK(parse_integer<DWORD>("16#dead_BEEF").value_or(0) == 0xDEADBEEFu);
    CHECK(parse_integer<DINT>("DINT#16#A1").value_or(0) == 0xA1);
    CHECK(parse_integer<INT>("INT#-5").value_or(0) == -5);
    CHECK(parse_integer<INT>("INT#16#FFFF").value_or(0) == -1);  // a based literal is a bit pattern
    CHECK(parse_integer<LINT>("-9223372036854775808").value_or(0) == std::numeric_limits<LINT>::min());
    CHECK(parse_integer<ULINT>("18446744073709551615").value_or(0) == std::numeric_limits<ULINT>::max());
    CHECK(parse_integer<USINT>("10#255").value_or(0) == 255);
  }

  TEST_CASE("invalid integer literals are rejected with their reason") {
    CHECK(parse_integer<INT>("").error() == parse_error::empty);
    CHECK(parse_integer<INT>("32768").error() == parse_error::out_of_range);
    CHECK(parse_integer<INT>("-32769").error() == parse_error::out_of_range);
    CHECK(parse_integer<UINT>("-1").error() == parse_error::negative);
    CHECK(parse_integer<BYTE>("16#100").error() == parse_error::out_of_range);
    CHECK(parse_integer<BYTE>("2#102").error() == parse_error::invalid_digit);
    CHECK(parse_integer<BYTE>("3#1").error() == parse_error::invalid_base);
    CHECK(parse_integer<INT>("-16#1").error() == parse_error::invalid_base);
    CHECK(parse_integer<INT>("DINT#5").error() == parse_error::wrong_prefix);
    CHECK(parse_integer<INT>("12xyz").error() == parse_error::trailing_characters);
    CHECK(parse_integer<INT>("12abc").error() == parse_error::invalid_digit);  // hex digits in a decimal
    CHECK(parse_integer<INT>("abc").error() == parse_error::expected_digit);
    CHECK(parse_integer<INT>("1__0").error() == parse_error::misplaced_underscore);
    CHECK(parse_integer<INT>("10_").error() == parse_error::misplaced_underscore);
    CHECK(parse_integer<INT>("INT#").error() == parse_error::no_value);
    CHECK(parse_integer<ULINT>("18446744073709551616").error() == parse_error::out_of_range);
  }

  TEST_CASE("BOOL literals") {
    CHECK(parse_bool("TRUE").value_or(FALSE) == TRUE);
    CHECK(parse_bool("false").value_or(TRUE) == FALSE);
    CHECK(parse_bool("BOOL#1").value_or(FALSE) == TRUE);
    CHECK(parse_bool("BOOL#0").value_or(TRUE) == FALSE);
    CHECK(parse_bool("yes").error() == parse_error::expected_digit);
    CHECK(parse_bool("INT#1").error() == parse_error::wrong_prefix);
    CHECK(parse_bool("").error() == parse_error::empty);
  }

  TEST_CASE("REAL and LREAL text") {
    CHECK(parse_real<REAL>("1.5").value_or(0) == 1.5f);
    CHECK(parse_real<LREAL>("-2.0E-3").value_or(0) == -0.002);
    CHECK(parse_real<LREAL>("1_000.25").value_or(0) == 1000.25);
    CHECK(parse_real<REAL>("REAL#2.5").value_or(0) == 2.5f);
    CHECK(parse_real<LREAL>("+7").value_or(0) == 7.0);
    CHECK(parse_real<REAL>("1e99").error() == parse_error::out_of_range);
    CHECK(parse_real<REAL>("1.5x").error() == parse_error::trailing_characters);
    CHECK(parse_real<REAL>("LREAL#1.0").error() == parse_error::wrong_prefix);
    CHECK(parse_real<REAL>("inf").error() == parse_error::expected_digit);
    CHECK(parse_real<REAL>("1.0.0").error() == parse_error::trailing_characters);
  }

  TEST_CASE("values format back to IEC text") {
    char text[64];
    const auto show = [&text](auto value) {
      return std::string_view(text, static_cast<std::size_t>(to_text(text, value) - text));
    };
    CHECK(show(TIME()) == "T#0ms");
    CHECK(show(TIME(12)) == "T#12ms");
    CHECK(show(TIME(3723004)) == "T#1h2m3s4ms");
    CHECK(show(TIME::max()) == "T#49d17h2m47s295ms");
    CHECK(show(TIME(90000)) == "T#1m30s");
    CHECK(show(LTIME()) == "LTIME#0ns");
    CHECK(show(LTIME::from_ticks(1500000)) == "LTIME#1ms500us");
    CHECK(show(LTIME::max()) == "LTIME#213503d23h34m33s709ms551us615ns");
    CHECK(show(INT(-32768)) == "-32768");
    CHECK(show(ULINT(18446744073709551615u)) == "18446744073709551615");
    CHECK(show(LINT(std::numeric_limits<std::int64_t>::min())) == "-9223372036854775808");
    CHECK(show(BYTE(0)) == "0");
    CHECK(show(TRUE) == "TRUE");
    CHECK(show(FALSE) == "FALSE");
    CHECK(show(REAL(1.5f)) == "1.5");
    CHECK(show(LREAL(-0.1)) == "-0.1");
    CHECK(show(TIME::max()).size() < max_text_length<TIME>);  // not the longest text: see below
    CHECK(show(LTIME::max()).size() == max_text_length<LTIME>);
  }

  TEST_CASE("no TIME or LTIME text is longer than max_text_length, the longest included") {
    // The longest texts are not those of the largest values: every unit with two digits.
    static_assert(max_text_length<TIME> == 19);
    static_assert(max_text_length<LTIME> == 37);
    char text[64];
    const auto length = [&text](auto value) { return static_cast<std::size_t>(to_text(text, value) - text); };
    const TIME tLongest = TIME::from_ticks(11U * 86'400'000U + 86'399'999U);
    CHECK(std::string_view(text, length(tLongest)) == "T#11d23h59m59s999ms");
    CHECK(length(tLongest) == max_text_length<TIME>);
    CHECK(std::string(TIME_TO_STRING(tLongest).view()) == "T#11d23h59m59s999ms");
    std::ostringstream os;  // operator<< and fmt size their buffers from max_text_length too
    os << tLongest;
    CHECK(os.str() == "T#11d23h59m59s999ms");
    CHECK(fmt::format("{}", tLongest) == "T#11d23h59m59s999ms");
    // Every day count with the longest time of day, and 2,000,000 pseudo-random values of each.
    std::size_t longest = 0;
    for (std::uint32_t d = 0; d <= 49; ++d) {
      const std::uint64_t ms = std::uint64_t{d} * 86'400'000U + 86'399'999U;
      if (ms <= 0xFFFF'FFFFU) longest = std::max(longest, length(TIME::from_ticks(static_cast<std::uint32_t>(ms))));
    }
    std::uint64_t x = 0x9E37'79B9'7F4A'7C15ULL;
    std::size_t longest_ltime = 0;
    for (int i = 0; i < 2'000'000; ++i) {
      x = x * 6364136223846793005ULL + 1442695040888963407ULL;
      longest = std::max(longest, length(TIME::from_ticks(static_cast<std::uint32_t>(x >> 32))));
      longest_ltime = std::max(longest_ltime, length(LTIME::from_ticks(x)));
    }
    CHECK(longest == max_text_length<TIME>);
    CHECK(longest_ltime <= max_text_length<LTIME>);
    CHECK(length(LTIME::from_ticks(99'999ULL * 86'400'000'000'000ULL + 86'399'999'999'999ULL)) <=
          max_text_length<LTIME>);
  }

  TEST_CASE("a fraction counts as a whole: exact sums are taken, nothing finer is dropped") {
    // Each digit alone is not a whole number of ns, the sum is: 0.000000000005 d = 432 ns.
    CHECK(parse_ltime("LTIME#1.000000000005d").value_or({}) == LTIME::from_ticks(86'400'000'000'432ULL));
    CHECK(parse_ltime("LTIME#0.5us").value_or({}) == LTIME::from_ticks(500));
    CHECK(parse_time("T#1.25s").value_or({}) == TIME::from_ticks(1250));
    CHECK(parse_time("T#1.000_000s").value_or({}) == TIME::from_ticks(1000));  // trailing zeros
    // Finer than the type resolves, however far back the digit stands.
    CHECK(parse_ltime("LTIME#1.05ns").error() == parse_error::too_precise);
    CHECK(parse_time("T#1.00000000001s").error() == parse_error::too_precise);
    CHECK(parse_time("T#1.0001s").error() == parse_error::too_precise);
    CHECK(parse_ltime("LTIME#1.0000000000000001d").error() == parse_error::too_precise);
  }

  TEST_CASE("a literal whose lower unit overflows: the same duration spelt validly, or its other error") {
    // What the diagnostic of "..."_iec proposes (tests/compile_fail/literal_unit_overflow*.cpp).
    CHECK(detail::normalized_duration<TIME>("t#5m68s").value_or({}) == TIME::from_ticks(368'000));
    CHECK(detail::normalized_duration<LTIME>("LT#1h60m").value_or({}) == LTIME::from_ticks(7'200'000'000'000ULL));
    // Wrong besides: a later error (it proposed T#0ms), a duration beyond TIME (it proposed the
    // duration wrapped to 32 bits, T#704ms).
    CHECK(detail::normalized_duration<TIME>("T#5m68s1x").error() == parse_error::unknown_unit);
    CHECK(detail::normalized_duration<LTIME>("LT#1s1000ms_").error() == parse_error::misplaced_underscore);
    CHECK(detail::normalized_duration<TIME>("T#49d17h2m47s1000ms").error() == parse_error::out_of_range);
    CHECK(detail::normalized_duration<TIME>("T#49d17h2m47s295ms").value_or({}) == TIME::max());
  }

  TEST_CASE("a REAL has one sign") {
    CHECK(parse_real<REAL>("+-1.5").error() == parse_error::expected_digit);
    CHECK(parse_real<LREAL>("++1.5").error() == parse_error::expected_digit);
    CHECK(parse_real<REAL>("+1.5").value_or({}) == 1.5f);
    CHECK(parse_real<REAL>("-1.5").value_or({}) == -1.5f);
  }

  TEST_CASE("formatting and parsing round-trip") {
    char text[64];
    for (const std::uint32_t ms : {0u, 1u, 999u, 1000u, 59999u, 3600000u, 86399999u, 4294967295u}) {
      const std::string_view s(text, static_cast<std::size_t>(to_text(text, TIME::from_ticks(ms)) - text));
      CAPTURE(s);
      CHECK(parse_time(s).value_or(TIME(1)) == TIME::from_ticks(ms));
    }
  }
}
