// DATE, TIME_OF_DAY, DATE_AND_TIME and their L forms: CODESYS's representation and ranges,
// the literals, the text both ways, the operators CODESYS allows, the conversions and the IEC
// functions of time data types (ADD_*, SUB_*, CONCAT_*, SPLIT_*, DAY_OF_WEEK).
#include "iecoop_test.hpp"

#include <iecoop/fmt.hpp>
#include <iecoop/runtime/retain.hpp>

#include <chrono>
#include <cstdint>
#include <limits>
#include <sstream>
#include <string>
#include <string_view>
#include <type_traits>

#include <fmt/format.h>

using namespace iecoop;
using iecoop_test::fault_recorder;
using iecoop_test::opaque;

// --- Representation (CDS-DATE: DWORD seconds / ms, LWORD nanoseconds) ---------------------

static_assert(sizeof(DATE) == 4 && sizeof(TOD) == 4 && sizeof(DT) == 4);
static_assert(sizeof(LDATE) == 8 && sizeof(LTOD) == 8 && sizeof(LDT) == 8);
static_assert(std::is_same_v<DATE::rep, std::uint32_t> && std::is_same_v<DATE::period, std::ratio<1>>);
static_assert(std::is_same_v<TOD::rep, std::uint32_t> && std::is_same_v<TOD::period, std::milli>);
static_assert(std::is_same_v<DT::rep, std::uint32_t> && std::is_same_v<DT::period, std::ratio<1>>);
static_assert(std::is_same_v<LDATE::rep, std::uint64_t> && std::is_same_v<LDATE::period, std::nano>);
static_assert(std::is_same_v<LTOD::rep, std::uint64_t> && std::is_same_v<LDT::rep, std::uint64_t>);
static_assert(std::is_same_v<TOD, TIME_OF_DAY> && std::is_same_v<DT, DATE_AND_TIME> &&
              std::is_same_v<LTOD, LTIME_OF_DAY> && std::is_same_v<LDT, LDATE_AND_TIME>);
static_assert(std::is_trivially_copyable_v<DATE> && std::is_trivially_copyable_v<LDT> &&
              std::is_trivially_copyable_v<TOD>);
static_assert(DATE().count() == 0 && TOD().count() == 0 && LDT().count() == 0);
static_assert(AnyDate<DATE> && AnyDate<LTOD> && AnyDate<LDT> && !AnyDate<TIME> && !AnyDate<UDINT>);
static_assert(AnyElementary<DT> && AnyElementary<LDATE>);
static_assert(detail::iec_name<DT>::value == "DT" && detail::iec_name<LTOD>::value == "LTOD");
// Never a number implicitly, in either direction.
static_assert(!std::is_convertible_v<DATE, UDINT> && !std::is_convertible_v<DATE, std::uint32_t> &&
              !std::is_constructible_v<std::uint32_t, DATE> && !std::is_constructible_v<UDINT, DATE>);
static_assert(!std::is_convertible_v<std::uint32_t, DATE> && !std::is_convertible_v<UDINT, DT> &&
              !std::is_convertible_v<TIME, TOD> && !std::is_convertible_v<TOD, TIME>);
// The 32-bit forms widen implicitly to the L forms (of their own kind only); back is explicit.
static_assert(std::is_convertible_v<DATE, LDATE> && std::is_convertible_v<TOD, LTOD> && std::is_convertible_v<DT, LDT>);
static_assert(!std::is_convertible_v<LDATE, DATE> && std::is_constructible_v<DATE, LDATE>);
static_assert(!std::is_constructible_v<DT, DATE> && !std::is_constructible_v<LDT, DATE> &&
              !std::is_constructible_v<TOD, DT>);
// The operators CODESYS allows, with the types CODESYS gives.
static_assert(std::is_same_v<decltype(TOD() + TIME()), TOD> && std::is_same_v<decltype(DT() + TIME()), DT>);
static_assert(std::is_same_v<decltype(TOD() + LTIME()), LTOD> && std::is_same_v<decltype(DT() + LTIME()), LDT>);
static_assert(std::is_same_v<decltype(LTOD() + TIME()), LTOD> && std::is_same_v<decltype(LDT() + LTIME()), LDT>);
static_assert(std::is_same_v<decltype(DATE() - DATE()), TIME> && std::is_same_v<decltype(LDATE() - LDATE()), LTIME>);
static_assert(std::is_same_v<decltype(TOD() - TOD()), TIME> && std::is_same_v<decltype(DT() - DT()), TIME>);
static_assert(std::is_same_v<decltype(DT() - LDT()), LTIME> && std::is_same_v<decltype(TOD() - TIME()), TOD>);
static_assert(std::is_same_v<decltype(LDT() - LTIME()), LDT>);
static_assert(std::is_same_v<decltype(TOD() < LTOD()), BOOL>);

// The ranges CODESYS documents, as literals.
static_assert("D#1970-01-01"_iec.count() == 0);
static_assert("D#2106-02-07"_iec.count() == 4'294'944'000U);  // the last whole day
static_assert("DT#2106-02-07-06:28:15"_iec == DT::max());
static_assert("TOD#23:59:59.999"_iec.count() == 86'399'999U);
static_assert("LTOD#23:59:59.999999999"_iec.count() == 86'399'999'999'999ULL);
static_assert("LDATE#2554-07-21"_iec.count() == 213'503ULL * 86'400 * 1'000'000'000);
static_assert("LDT#2554-07-21-23:34:33.709551615"_iec == LDT::max());

namespace {

template <class T>
std::string text_of(T value) {
  char buffer[max_text_length<T> + 8];
  for (char& c : buffer) c = '\x7F';
  const char* end = to_text(buffer, value);
  // Nothing written past the longest text the type declares.
  bool guard_intact = static_cast<std::size_t>(end - buffer) <= max_text_length<T>;
  for (std::size_t i = max_text_length<T>; i < sizeof(buffer); ++i) guard_intact = guard_intact && buffer[i] == '\x7F';
  if (!guard_intact) FAIL_CHECK("to_text wrote past max_text_length");
  return std::string(buffer, static_cast<std::size_t>(end - buffer));
}

/// An independent count of days since 1970 for y-m-d, from the standard library's calendar.
std::uint64_t chrono_days(int y, unsigned m, unsigned d) {
  using namespace std::chrono;
  return static_cast<std::uint64_t>(sys_days(year(y) / month(m) / day(d)).time_since_epoch().count());
}

}  // namespace

TEST_SUITE("date and time types") {
  TEST_CASE("literals give the CODESYS values") {
    CHECK("D#1970-01-02"_iec.count() == 86'400U);
    CHECK("DATE#2019-9-1"_iec.count() == 1'567'296'000U);
    CHECK("d#2020-2-7"_iec == "D#2020-02-07"_iec);
    CHECK("DT#2019-9-1-12:0:0"_iec.count() == 1'567'339'200U);  // CODESYS's DT_TO_DINT example
    CHECK("DATE_AND_TIME#2026-11-23-12:30:00"_iec.count() == 1'795'437'000U);
    CHECK("TOD#12:0:0"_iec.count() == 43'200'000U);  // CODESYS's TOD_TO_DINT example
    CHECK("TIME_OF_DAY#12:30:00.5"_iec.count() == 45'000'500U);
    CHECK("tod#0:0:0"_iec.count() == 0U);
    CHECK("LTOD#12:03:04.567890123"_iec.count() == 43'384'567'890'123ULL);
    CHECK("LTIME_OF_DAY#0:0:0.000000001"_iec.count() == 1U);
    CHECK("LDT#2020-2-7-12:55:1.234567891"_iec.count() == 1'581'080'101'234'567'891ULL);
    CHECK("LDATE_AND_TIME#1970-01-01-00:00:00.5"_iec.count() == 500'000'000U);
    CHECK("LD#2026-11-23"_iec.count() == 1'795'392'000ULL * 1'000'000'000);
    CHECK("DT#2026-11-23-12:30:00.000"_iec.count() == 1'795'437'000U);  // a fraction of zeros is whole seconds
    CHECK("TOD#12:30:00.1_2"_iec.count() == 45'000'120U);               // '_' between digits
    static_assert(std::is_same_v<decltype("LD#2026-11-23"_iec), LDATE>);
    static_assert(std::is_same_v<decltype("TIME_OF_DAY#1:0:0"_iec), TOD>);
  }

  TEST_CASE("leap years and month ends, at every year of LDATE's range") {
    for (int y = 1970; y <= 2553; ++y) {
      for (unsigned m = 1; m <= 12; ++m) {
        const std::uint64_t last = detail::days_in_month(static_cast<std::uint64_t>(y), m);
        const std::string month_text = std::to_string(y) + "-" + std::to_string(m) + "-";
        const auto ok = parse_ldate("LDATE#" + month_text + std::to_string(last));
        REQUIRE(ok);
        CHECK(ok.value_or(LDATE()).count() / 86'400'000'000'000ULL == chrono_days(y, m, static_cast<unsigned>(last)));
        const auto past = parse_ldate("LDATE#" + month_text + std::to_string(last + 1));
        CHECK(past.error() == parse_error::invalid_date);
      }
    }
    CHECK(parse_date("D#2000-02-29"));                                       // divisible by 400: a leap year
    CHECK(parse_date("D#2100-02-29").error() == parse_error::invalid_date);  // by 100 only: none
    CHECK(parse_ldate("LDATE#2400-02-29"));
    CHECK(parse_date("D#2024-02-29"));
    CHECK(parse_date("D#2023-02-29").error() == parse_error::invalid_date);
    CHECK(parse_date("D#2023-13-01").error() == parse_error::invalid_date);
    CHECK(parse_date("D#2023-00-10").error() == parse_error::invalid_date);
    CHECK(parse_date("D#2023-04-00").error() == parse_error::invalid_date);
    CHECK(parse_date("D#2023-04-31").error() == parse_error::invalid_date);
    CHECK("LDATE#2100-03-01"_iec - "LDATE#2100-02-28"_iec == "LTIME#1d"_iec);
    CHECK("D#2000-03-01"_iec - "D#2000-02-28"_iec == "T#2d"_iec);
  }

  TEST_CASE("the ends of each type's range") {
    CHECK(parse_date("D#1969-12-31").error() == parse_error::out_of_range);
    CHECK(parse_date("D#2106-02-08").error() == parse_error::out_of_range);
    CHECK(parse_dt("DT#2106-02-07-06:28:16").error() == parse_error::out_of_range);
    CHECK(parse_dt("DT#1969-12-31-23:59:59").error() == parse_error::out_of_range);
    CHECK(parse_ldate("LDATE#2554-07-22").error() == parse_error::out_of_range);
    CHECK(parse_ldt("LDT#2554-07-21-23:34:33.709551616").error() == parse_error::out_of_range);
    CHECK(parse_ldt("LDT#9999-12-31-23:59:59").error() == parse_error::out_of_range);
    CHECK(parse_date("D#99999999999999999999-01-01").error() == parse_error::out_of_range);
    CHECK(text_of(DATE::max()) == "D#2106-02-07");  // 06:28:15 into the last day: the day shows
    CHECK(text_of(DT::max()) == "DT#2106-02-07-06:28:15");
    CHECK(text_of(LDATE::max()) == "LDATE#2554-07-21");
    CHECK(text_of(LDT::max()) == "LDT#2554-07-21-23:34:33.709551615");
    CHECK(text_of(DT()) == "DT#1970-01-01-00:00:00");
    CHECK(text_of(LTOD()) == "LTOD#00:00:00");
  }

  TEST_CASE("the longest text of each type fits its max_text_length exactly") {
    // Built from the largest field values each type can hold.
    CHECK(text_of(DATE::max()).size() == max_text_length<DATE>);
    CHECK(text_of(LDATE::max()).size() == max_text_length<LDATE>);
    CHECK(text_of(DT::max()).size() == max_text_length<DT>);
    CHECK(text_of(LDT::max()).size() == max_text_length<LDT>);
    CHECK(text_of(TOD::max()) == "TOD#1193:02:47.295");
    CHECK(text_of(TOD::max()).size() == max_text_length<TOD>);
    CHECK(text_of(LTOD::max()) == "LTOD#5124095:34:33.709551615");
    CHECK(text_of(LTOD::max()).size() == max_text_length<LTOD>);
    // No TOD with four-digit hours is longer (text_of checks the buffer's end too).
    for (std::uint64_t ms = 3'600'000ULL * 1000 + 1; ms <= TOD::max().count(); ms += 3'600'001U) {
      CHECK(text_of(TOD::from_ticks(static_cast<std::uint32_t>(ms))).size() <= max_text_length<TOD>);
    }
    CHECK(text_of(TOD::from_ticks(1000U * 3'600'000U + 1)) == "TOD#1000:00:00.001");
    // Through STRING: TO_STRING of the longest value keeps every character.
    CHECK(LDT_TO_STRING(LDT::max()) == "LDT#2554-07-21-23:34:33.709551615");
    CHECK(TOD_TO_STRING(TOD::max()) == "TOD#1193:02:47.295");
  }

  TEST_CASE("every day of LDATE's range reads back from its text") {
    for (std::uint64_t day = 0; day <= 213'503; ++day) {
      const LDATE d = LDATE::from_ticks(day * 86'400'000'000'000ULL);
      const std::string text = text_of(d);
      const auto back = parse_ldate(text);
      REQUIRE_MESSAGE(back, text);
      CHECK(back.value_or(LDATE()) == d);
      if (day <= 49'710) {
        const DATE d32 = DATE::from_ticks(static_cast<std::uint32_t>(day * 86'400));
        CHECK(parse_date(text_of(d32)).value_or(DATE()) == d32);
        CHECK(text_of(d32).substr(2) == text.substr(6));
      }
    }
  }

  TEST_CASE("times of day and dates with times read back from their text") {
    for (std::uint32_t s = 0; s < 86'400; s += 7) {
      for (const std::uint32_t ms : {0U, 1U, 10U, 100U, 120U, 500U, 999U}) {
        const TOD t = TOD::from_ticks(s * 1000 + ms);
        CHECK(parse_tod(text_of(t)).value_or(TOD()) == t);
        const LTOD lt = LTOD::from_ticks((s * 1000ULL + ms) * 1'000'000ULL + ms * 1001ULL);
        CHECK(parse_ltod(text_of(lt)).value_or(LTOD()) == lt);
      }
    }
    // DT and LDT across their ranges, in uneven steps.
    for (std::uint64_t x = 0; x <= DT::max().count(); x += 9'876'543ULL) {
      const DT dt = DT::from_ticks(static_cast<std::uint32_t>(x));
      CHECK(parse_dt(text_of(dt)).value_or(DT()) == dt);
    }
    std::uint64_t state = 88172645463325252ULL;
    for (int i = 0; i < 20'000; ++i) {
      state ^= state << 13;
      state ^= state >> 7;
      state ^= state << 17;
      const LDT ldt = LDT::from_ticks(state);
      const std::string text = text_of(ldt);
      CHECK_MESSAGE(parse_ldt(text).value_or(LDT()) == ldt, text);
    }
    CHECK(text_of("TOD#12:30:00.5"_iec) == "TOD#12:30:00.5");
    CHECK(text_of("TOD#14:01:05.123"_iec) == "TOD#14:01:05.123");
    CHECK(text_of("LTOD#00:00:00.000000010"_iec) == "LTOD#00:00:00.00000001");
    CHECK(text_of("D#2002-08-18"_iec) == "D#2002-08-18");
  }

  TEST_CASE("text that is no point in time says why and where") {
    CHECK(parse_date("").error() == parse_error::empty);
    CHECK(parse_date("2026-11-23").error() == parse_error::missing_prefix);
    CHECK(parse_date("DT#2026-11-23").error() == parse_error::wrong_prefix);
    CHECK(parse_date("LDATE#2026-11-23").error() == parse_error::wrong_prefix);  // no narrowing in text
    CHECK(parse_ldate("D#2026-11-23"));                                          // a DATE widens
    CHECK(parse_ldt("DT#2026-11-23-12:00:00"));
    CHECK(parse_ltod("TOD#12:00:00"));
    CHECK(parse_date("D#").error() == parse_error::no_value);
    CHECK(parse_date("D#2026/11/23").error() == parse_error::expected_separator);
    CHECK(parse_date("D#2026/11/23").position() == 6);
    CHECK(parse_date("D#2026-11").error() == parse_error::expected_separator);
    CHECK(parse_date("D#2026-11-23x").error() == parse_error::trailing_characters);
    CHECK(parse_date("D#2026-11-23-12:00:00").error() == parse_error::trailing_characters);
    CHECK(parse_dt("DT#2026-11-23").error() == parse_error::expected_separator);
    CHECK(parse_dt("DT#2026-11-23-12:00").error() == parse_error::expected_separator);
    CHECK(parse_tod("TOD#24:00:00").error() == parse_error::invalid_time_of_day);
    CHECK(parse_tod("TOD#23:60:00").error() == parse_error::invalid_time_of_day);
    CHECK(parse_tod("TOD#23:59:60").error() == parse_error::invalid_time_of_day);
    CHECK(parse_tod("TOD#23:59:60").position() == 10);
    CHECK(parse_tod("TOD#12:00:00.0001").error() == parse_error::too_precise);
    CHECK(parse_dt("DT#2026-11-23-12:00:00.5").error() == parse_error::too_precise);
    CHECK(parse_ltod("LTOD#12:00:00.0000000001").error() == parse_error::too_precise);
    CHECK(parse_ltod("LTOD#12:00:00.1000000000"));  // trailing zeros below 1 ns are exact
    CHECK(parse_tod("TOD#12:00:00.").error() == parse_error::expected_digit);
    CHECK(parse_tod("TOD#12:00:-1").error() == parse_error::expected_digit);
    CHECK(parse_tod("TOD#12:_0:00").error() == parse_error::misplaced_underscore);
    CHECK(std::string_view(describe(parse_error::invalid_date)).find("date") != std::string_view::npos);
  }

  TEST_CASE("TOD and DT arithmetic is CODESYS's DWORD arithmetic") {
    // No wrap at midnight: the TOD holds the hours past it, and shows them.
    const TOD late = opaque("TOD#23:00:00"_iec);
    const TOD past = late + "T#2h"_iec;
    CHECK(past.count() == 90'000'000U);
    CHECK(text_of(past) == "TOD#25:00:00");
    CHECK(DT_TO_TOD(CONCAT_DATE_TOD("D#2026-11-23"_iec, past)) ==
          "TOD#01:00:00"_iec);  // a DT does wrap into the next day
    CHECK(CONCAT_DATE_TOD("D#2026-11-23"_iec, past) == "DT#2026-11-24-01:00:00"_iec);
    // Below midnight: modulo 2^32 ms.
    CHECK((opaque("TOD#00:00:00"_iec) - "T#1s"_iec).count() == 4'294'966'296U);
    CHECK(opaque("TOD#00:00:01"_iec) - "TOD#00:00:02"_iec == TIME::from_ticks(4'294'966'296U));
    // DT counts seconds: a duration's milliseconds are dropped.
    CHECK(opaque("DT#2026-11-23-12:30:00"_iec) + "T#1s999ms"_iec == "DT#2026-11-23-12:30:01"_iec);
    CHECK(opaque("DT#1970-01-01-00:00:00"_iec) - "T#1s"_iec == DT::max());
    CHECK(opaque(DT::max()) + "T#1s"_iec == DT());
    // A difference is a TIME, which holds 49 days: longer ones wrap, as in CODESYS.
    CHECK("DT#2026-11-23-14:00:00"_iec - "DT#2026-11-23-12:30:00"_iec == "T#1h30m"_iec);
    CHECK("D#2026-02-18"_iec - "D#2026-01-01"_iec == "T#48d"_iec);
    CHECK((opaque("D#2026-03-01"_iec) - "D#2026-01-01"_iec).count() == static_cast<std::uint32_t>(59ULL * 86'400'000));
    CHECK(opaque("LDATE#2026-03-01"_iec) - "D#2026-01-01"_iec == "LTIME#59d"_iec);  // LTIME holds it
    // An earlier point first wraps too.
    CHECK(opaque("D#2026-01-01"_iec) - "D#2026-01-02"_iec == TIME::from_ticks(4'294'967'296ULL - 86'400'000));
    // The L forms: LTOD + TIME widens the TIME; TOD + LTIME gives an LTOD.
    CHECK(opaque("LTOD#23:59:59.999999999"_iec) + "T#1ms"_iec == LTOD::from_ticks(86'400'000'999'999ULL));
    CHECK("TOD#12:00:00"_iec + "LTIME#1us"_iec == "LTOD#12:00:00.000001"_iec);
    CHECK("DT#2026-11-23-12:00:00"_iec + "LTIME#1ns"_iec == "LDT#2026-11-23-12:00:00.000000001"_iec);
    CHECK(opaque(LDT::max()) + "LTIME#1ns"_iec == LDT());
    TOD t = "TOD#08:00:00"_iec;
    t += "T#30m"_iec;
    t -= "T#1s"_iec;
    CHECK(t == "TOD#08:29:59"_iec);
    DT dt = "DT#2026-11-23-12:00:00"_iec;
    dt += "T#1d"_iec;
    CHECK(dt == "DT#2026-11-24-12:00:00"_iec);
  }

  TEST_CASE("comparisons yield BOOL and widen the 32-bit form") {
    CHECK(("D#2026-11-23"_iec < "D#2026-11-24"_iec) == TRUE);
    CHECK(("D#2026-11-23"_iec == "LDATE#2026-11-23"_iec) == TRUE);
    CHECK(("LDT#2026-11-23-12:00:00.5"_iec > "DT#2026-11-23-12:00:00"_iec) == TRUE);
    CHECK(("TOD#12:00:00"_iec >= "TOD#12:00:00"_iec) == TRUE);
    CHECK(("TOD#12:00:00"_iec != "TOD#12:00:00.001"_iec) == TRUE);
    CHECK(("D#2026-11-23"_iec <=> "D#2026-11-22"_iec) == std::strong_ordering::greater);
    CHECK(MAX("D#2026-11-23"_iec, "D#2026-11-24"_iec, "D#2025-01-01"_iec) == "D#2026-11-24"_iec);
    static_assert(std::is_same_v<decltype(MAX("D#2026-11-23"_iec, "LDATE#2026-11-24"_iec)), LDATE>);
    CHECK(LIMIT("TOD#08:00:00"_iec, "TOD#20:00:00"_iec, "TOD#18:00:00"_iec) == "TOD#18:00:00"_iec);
    CHECK(SEL(TRUE, "DT#2026-11-23-00:00:00"_iec, "DT#2026-11-24-00:00:00"_iec) == "DT#2026-11-24-00:00:00"_iec);
  }

  TEST_CASE("conversions follow CODESYS") {
    const DT dt = "DT#2026-11-23-12:30:45"_iec;
    CHECK(DT_TO_DATE(dt) == "D#2026-11-23"_iec);
    CHECK(DT_TO_TOD(dt) == "TOD#12:30:45"_iec);
    CHECK(DATE_TO_DT("D#2026-11-23"_iec) == "DT#2026-11-23-00:00:00"_iec);
    CHECK(LDT_TO_LTOD("LDT#2026-11-23-12:30:45.123456789"_iec) == "LTOD#12:30:45.123456789"_iec);
    CHECK(LDT_TO_DT("LDT#2026-11-23-12:30:45.999999999"_iec) == dt);  // truncates to the second
    CHECK(LDT_TO_DATE("LDT#2026-11-23-12:30:45.9"_iec) == "D#2026-11-23"_iec);
    CHECK(DT_TO_LDT(DT::max()) == "LDT#2106-02-07-06:28:15"_iec);
    CHECK(LTOD_TO_TOD("LTOD#12:00:00.0019"_iec) == "TOD#12:00:00.001"_iec);
    CHECK(LDATE_TO_DATE("LDATE#2200-01-01"_iec).count() ==
          static_cast<std::uint32_t>(chrono_days(2200, 1, 1) * 86'400));  // wraps modulo 2^32 s
    CHECK(DATE_TO_UDINT("D#1970-01-02"_iec) == 86'400U);
    CHECK(DATE_TO_DINT("D#2019-9-1"_iec) == 1'567'296'000);
    CHECK(DT_TO_DINT("DT#1970-1-1-0:0:1"_iec) == 1);
    CHECK(TOD_TO_DINT("TOD#12:0:0"_iec) == 43'200'000);
    CHECK(LDT_TO_ULINT(LDT::max()) == std::numeric_limits<std::uint64_t>::max());
    CHECK(DATE_TO_BOOL("D#1970-1-1"_iec) == FALSE);
    CHECK(DATE_TO_BOOL("D#2019-9-1"_iec) == TRUE);
    CHECK(TOD_TO_BOOL("TOD#0:0:0"_iec) == FALSE);
    CHECK(BOOL_TO_TOD(TRUE).count() == 1U);
    CHECK(UDINT_TO_DATE(UDINT(86'400)) == "D#1970-01-02"_iec);
    CHECK(UDINT_TO_DT(UDINT(1'795'437'000)) == "DT#2026-11-23-12:30:00"_iec);
    CHECK(DINT_TO_TOD(DINT(-1)) == TOD::max());  // keeps the low bytes
    CHECK(TO_DATE(86'400) == "D#1970-01-02"_iec);
    CHECK(DT_TO_LREAL(dt) == 1'795'437'045.0);
    CHECK(REAL_TO_TOD(REAL(1.5f)).count() == 2U);  // rounds
    // A DATE holding seconds past midnight (UDINT_TO_DATE can make one) shows its day.
    CHECK(DATE_TO_STRING(UDINT_TO_DATE(UDINT(86'401))) == "D#1970-01-02");
    CHECK(DATE_TO_STRING("D#2002-08-18"_iec) == "D#2002-08-18");
    CHECK(TOD_TO_STRING("TOD#14:01:05.123"_iec) == "TOD#14:01:05.123");
    CHECK(DT_TO_STRING(dt) == "DT#2026-11-23-12:30:45");
    CHECK(TO_STRING("LDATE#2300-01-01"_iec) == "LDATE#2300-01-01");
    CHECK(DT_TO_WSTRING(dt) == u"DT#2026-11-23-12:30:45");
    CHECK(STRING_TO_DT(" DT#2026-11-23-12:30:45 ") == dt);
    CHECK(STRING_TO_DATE("D#2100-02-29") == DATE());  // no such date: 0, as for any invalid text
    CHECK(STRING_TO_TOD("TOD#25:00:00") == TOD());
    CHECK(STRING_TO_LDT("DT#2026-11-23-12:30:45") == "LDT#2026-11-23-12:30:45"_iec);
    CHECK(WSTRING_TO_TOD(u"TOD#01:02:03") == "TOD#01:02:03"_iec);
    static_assert(DT_TO_DATE("DT#2026-11-23-12:30:45"_iec) == "D#2026-11-23"_iec);
  }

  TEST_CASE("the functions of IEC's table of time data types") {
    CHECK(ADD_TIME("T#1s"_iec, "T#500ms"_iec) == "T#1s500ms"_iec);
    CHECK(ADD_LTIME("LTIME#1s"_iec, "T#1ms"_iec) == "LTIME#1s1ms"_iec);
    CHECK(ADD_TOD_TIME("TOD#23:00:00"_iec, "T#2h"_iec).count() == 90'000'000U);
    CHECK(ADD_LTOD_LTIME("LTOD#13:00:00"_iec, "LTIME#1h"_iec) == "LTOD#14:00:00"_iec);
    CHECK(ADD_DT_TIME("DT#2011-12-24-18:29:59"_iec, "T#2h35m38s560ms"_iec) == "DT#2011-12-24-21:05:37"_iec);
    CHECK(ADD_LDT_LTIME("LDT#2026-11-23-12:00:00"_iec, "LTIME#1d"_iec) == "LDT#2026-11-24-12:00:00"_iec);
    CHECK(SUB_TIME("T#0ms"_iec, "T#1ms"_iec) == TIME::max());
    CHECK(SUB_LTIME("LTIME#1s"_iec, "LTIME#1ms"_iec) == "LTIME#999ms"_iec);
    CHECK(SUB_DATE_DATE("D#2026-11-24"_iec, "D#2026-11-23"_iec) == "T#1d"_iec);
    CHECK(SUB_LDATE_LDATE("LDATE#2554-07-21"_iec, "LDATE#1970-01-01"_iec) == "LTIME#213503d"_iec);
    CHECK(SUB_TOD_TIME("TOD#14:00:00"_iec, "T#1h"_iec) == "TOD#13:00:00"_iec);
    CHECK(SUB_LTOD_LTIME("LTOD#14:00:00"_iec, "LTIME#1ns"_iec) == "LTOD#13:59:59.999999999"_iec);
    CHECK(SUB_TOD_TOD("TOD#23:59:59.999"_iec, "TOD#23:59:50"_iec) == "T#9s999ms"_iec);
    CHECK(SUB_LTOD_LTOD("LTOD#00:00:01"_iec, "LTOD#00:00:00.5"_iec) == "LTIME#500ms"_iec);
    CHECK(SUB_DT_TIME("DT#2026-11-23-00:00:00"_iec, "T#1s"_iec) == "DT#2026-11-22-23:59:59"_iec);
    CHECK(SUB_LDT_LTIME("LDT#2026-11-23-00:00:00"_iec, "LTIME#1ns"_iec) == "LDT#2026-11-22-23:59:59.999999999"_iec);
    CHECK(SUB_DT_DT("DT#2026-11-23-12:00:00"_iec, "DT#2026-11-23-11:00:00"_iec) == "T#1h"_iec);
    CHECK(SUB_LDT_LDT("LDT#2026-11-23-12:00:00"_iec, "LDT#2026-11-22-12:00:00"_iec) == "LTIME#1d"_iec);
    CHECK(MUL_TIME("T#1s"_iec, 3) == "T#3s"_iec);
    CHECK(MUL_TIME("T#1s"_iec, REAL(1.5f)) == "T#1s500ms"_iec);
    CHECK(MUL_LTIME("LTIME#1ns"_iec, INT(7)) == "LTIME#7ns"_iec);
    CHECK(DIV_TIME("T#1s"_iec, 4) == "T#250ms"_iec);
    CHECK(DIV_LTIME("LTIME#1us"_iec, 3) == "LTIME#333ns"_iec);
    fault_recorder faults;
    CHECK(DIV_TIME("T#1s"_iec, opaque(INT(0))) == TIME());
    CHECK(faults.last_kind == fault_kind::division_by_zero);
    CHECK(CONCAT_DATE_TOD("D#2026-11-23"_iec, "TOD#12:30:00.999"_iec) == "DT#2026-11-23-12:30:00"_iec);
    CHECK(CONCAT_LDATE_LTOD("LDATE#2026-11-23"_iec, "LTOD#12:30:00.5"_iec) == "LDT#2026-11-23-12:30:00.5"_iec);
    CHECK(DAY_OF_WEEK("D#1970-01-01"_iec) == 4);  // a Thursday
    CHECK(DAY_OF_WEEK("D#2000-01-01"_iec) == 6);  // a Saturday
    CHECK(DAY_OF_WEEK("D#2000-02-29"_iec) == 2);
    CHECK(DAY_OF_WEEK("D#2026-11-23"_iec) == 1);  // a Monday
    CHECK(DAY_OF_WEEK("D#2106-02-07"_iec) == 0);  // a Sunday
    CHECK(DAY_OF_WEEK("LDATE#2100-03-01"_iec) == 1);
    static_assert(std::is_same_v<decltype(DAY_OF_WEEK(DATE())), USINT>);
  }

  TEST_CASE("CONCAT checks its components and SPLIT gives them back") {
    CHECK(CONCAT_DATE(2026, 11, 23) == "D#2026-11-23"_iec);
    CHECK(CONCAT_DATE(INT(2000), USINT(2), SINT(29)) == "D#2000-02-29"_iec);
    CHECK(CONCAT_TOD(23, 59, 59, 999) == "TOD#23:59:59.999"_iec);
    CHECK(CONCAT_LTOD(0, 0, 0, 1) == "LTOD#00:00:00.001"_iec);
    CHECK(CONCAT_DT(2106, 2, 7, 6, 28, 15, 999) == DT::max());  // DT drops the milliseconds
    CHECK(CONCAT_LDT(2554, 7, 21, 23, 34, 33, 709) == "LDT#2554-07-21-23:34:33.709"_iec);
    const INT year = 2026;
    CHECK(CONCAT_DATE(year + 1, 1, 1) == "D#2027-01-01"_iec);  // an intermediate result
    fault_recorder faults;
    struct bad_input {
      int y, mo, d, h, mi, s, ms;
    };
    for (const bad_input& b :
         {bad_input{2100, 2, 29, 0, 0, 0, 0}, bad_input{2026, 13, 1, 0, 0, 0, 0}, bad_input{2026, 4, 31, 0, 0, 0, 0},
          bad_input{1969, 12, 31, 0, 0, 0, 0}, bad_input{2106, 2, 7, 6, 28, 16, 0}, bad_input{2026, 1, 1, 24, 0, 0, 0},
          bad_input{2026, 1, 1, 0, 60, 0, 0}, bad_input{2026, 1, 1, 0, 0, 60, 0}, bad_input{2026, 1, 1, 0, 0, 0, 1000},
          bad_input{2026, 1, 1, -1, 0, 0, 0}}) {
      const int before = faults.count;
      CHECK(CONCAT_DT(b.y, b.mo, b.d, b.h, b.mi, b.s, b.ms) == DT());
      CHECK(faults.count == before + 1);
      CHECK(faults.last_kind == fault_kind::invalid_value);
    }
    CHECK(CONCAT_DATE(2106, 2, 8) == DATE());
    CHECK(faults.last_message.find("CONCAT_DATE") != std::string::npos);
    CHECK(CONCAT_TOD(24, 0, 0, 0) == TOD());
    CHECK(CONCAT_LDT(2554, 7, 21, 23, 34, 33, 710) == LDT());
    CHECK(CONCAT_DATE(ULINT(std::numeric_limits<std::uint64_t>::max()), 1, 1) == DATE());
    const int faults_so_far = faults.count;

    // Round trips over the whole of DATE's range, a day in 13, and over a day in steps.
    INT y = 0;
    UINT mo = 0;
    DINT d = 0;
    for (std::uint32_t day = 0; day <= 49'710; day += 13) {
      const DATE in = DATE::from_ticks(day * 86'400);
      SPLIT_DATE(in, y, mo, d);
      CHECK(CONCAT_DATE(y, mo, d) == in);
    }
    USINT h = 0;
    USINT mi = 0;
    USINT s = 0;
    UINT ms = 0;
    for (std::uint32_t t = 0; t < 86'400'000; t += 997) {
      const TOD in = TOD::from_ticks(t);
      SPLIT_TOD(in, h, mi, s, ms);
      CHECK(CONCAT_TOD(h, mi, s, ms) == in);
    }
    for (std::uint64_t x = 0; x <= DT::max().count(); x += 7'654'321) {
      const DT in = DT::from_ticks(static_cast<std::uint32_t>(x));
      SPLIT_DT(in, y, mo, d, h, mi, s, ms);
      CHECK(ms == 0U);
      CHECK(CONCAT_DT(y, mo, d, h, mi, s, ms) == in);
    }
    SPLIT_LDT("LDT#2554-07-21-23:34:33.709551615"_iec, y, mo, d, h, mi, s, ms);
    CHECK(y == 2554);
    CHECK(mo == 7U);
    CHECK(d == 21);
    CHECK(h == 23U);
    CHECK(mi == 34U);
    CHECK(s == 33U);
    CHECK(ms == 709U);  // to the millisecond
    SPLIT_LTOD("LTOD#01:02:03.004999"_iec, h, mi, s, ms);
    CHECK((h == 1U && mi == 2U && s == 3U && ms == 4U));
    SPLIT_TOD("TOD#23:00:00"_iec + "T#2h"_iec, h, mi, s, ms);
    CHECK(h == 25U);  // a TOD past midnight splits into its hours past 23
    CHECK(faults.count == faults_so_far);
    // An output too narrow for its value: a fault, and the low bytes.
    SINT sYear = 0;
    SPLIT_DATE("D#2026-11-23"_iec, sYear, mo, d);
    CHECK(faults.count == faults_so_far + 1);
    CHECK(sYear == static_cast<std::int8_t>(2026 & 0xFF));
  }

  TEST_CASE("points in time print, format, and are kept as RETAIN") {
    std::ostringstream out;
    out << "D#2026-11-23"_iec << ' ' << "TOD#12:30:00.5"_iec << ' ' << "LDT#2026-11-23-12:30:00.25"_iec;
    CHECK(out.str() == "D#2026-11-23 TOD#12:30:00.5 LDT#2026-11-23-12:30:00.25");
    CHECK(fmt::format("{}", "DT#2026-11-23-12:30:00"_iec) == "DT#2026-11-23-12:30:00");
    CHECK(fmt::format("[{:>14}]", "D#2026-11-23"_iec) == "[  D#2026-11-23]");
    retain<DT> dtLast{"DT#2026-11-23-12:30:00"_iec};  // a variable wrapper, as var<> is
    CHECK(fmt::format("{}", dtLast) == "DT#2026-11-23-12:30:00");
    CHECK(dtLast + "T#1m"_iec == "DT#2026-11-23-12:31:00"_iec);
    CHECK(dtLast - "DT#2026-11-23-12:00:00"_iec == "T#30m"_iec);
    CHECK(DT_TO_DATE(dtLast) == "D#2026-11-23"_iec);
    const LDT widened = dtLast;
    CHECK(widened == "LDT#2026-11-23-12:30:00"_iec);
    dtLast = "DT#2026-11-24-00:00:00"_iec;
    CHECK(dtLast == "DT#2026-11-24-00:00:00"_iec);
    static_assert(detail::type_hash<DT> == detail::fnv1a().add("DT").value());
    static_assert(detail::type_hash<DT> != detail::type_hash<UDINT> &&
                  detail::type_hash<DT> != detail::type_hash<DATE>);
  }
}
