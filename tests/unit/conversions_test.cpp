// The IEC conversion functions: every kind-to-kind rule with CODESYS's documented
// examples, the edge cases (rounding halves, out-of-range REALs, invalid text), and a sweep
// over every pair of elementary types.
#include "iecoop_test.hpp"

#include <cmath>
#include <limits>
#include <string_view>
#include <tuple>
#include <type_traits>

using namespace iecoop;

namespace {

using elementary_types = std::tuple<BOOL, BYTE, WORD, DWORD, LWORD, SINT, INT, DINT, LINT, USINT, UINT, UDINT, ULINT,
                                    REAL, LREAL, TIME, LTIME, STRING<>, WSTRING<>>;

// The text a zero of each type converts to.
template <class T>
constexpr std::string_view zero_text() {
  if constexpr (std::is_same_v<T, BOOL>)
    return "FALSE";
  else if constexpr (std::is_same_v<T, TIME>)
    return "T#0ms";
  else if constexpr (std::is_same_v<T, LTIME>)
    return "LTIME#0ns";
  else if constexpr (AnyString<T>)
    return "";
  else
    return "0";
}

template <class To, class From>
void check_zero_converts(int& checked) {
  const To result = convert<To>(From{});
  static_assert(std::is_same_v<decltype(convert<To>(From{})), To>);
  if constexpr (AnyString<To>) {
    CHECK(convert<STRING<>>(result) == zero_text<From>());
  } else {
    CHECK(result == To{});  // zero, FALSE, T#0ms: from zero, FALSE, T#0ms and ''
  }
  ++checked;
}

template <class From, class... To>
void check_zero_from(int& checked, std::tuple<To...>*) {
  (check_zero_converts<To, From>(checked), ...);
}

template <class... From>
int check_all_pairs(std::tuple<From...>* all) {
  int checked = 0;
  (check_zero_from<From>(checked, all), ...);
  return checked;
}

}  // namespace

// A sample of the generated names, with the types they take and give.
static_assert(std::is_same_v<decltype(INT_TO_DINT(INT())), DINT>);
static_assert(std::is_same_v<decltype(REAL_TO_INT(REAL())), INT>);
static_assert(std::is_same_v<decltype(TIME_TO_STRING(TIME())), STRING<80>>);
static_assert(std::is_same_v<decltype(LTIME_TO_WSTRING(LTIME())), WSTRING<80>>);
static_assert(std::is_same_v<decltype(WSTRING_TO_LTIME(u"")), LTIME>);
static_assert(std::is_same_v<decltype(STRING_TO_BOOL(STRING<7>())), BOOL>);
static_assert(std::is_same_v<decltype(TO_LWORD(1)), LWORD>);
// A named conversion takes its source type, or what converts to it implicitly; another type is
// refused with a message naming both (tests/compile_fail/conversion_wrong_source.cpp).
static_assert(detail::conversion_source<INT, SINT> && !detail::conversion_source<INT, DINT>);
static_assert(!detail::conversion_source<TIME, DINT> && !std::is_invocable_v<decltype(STRING_TO_INT), INT>);

TEST_SUITE("conversions") {
  TEST_CASE("every pair of elementary types converts, zero to zero") {
    CHECK(check_all_pairs(static_cast<elementary_types*>(nullptr)) == 19 * 19);
  }

  TEST_CASE("integer to integer keeps the low bytes") {
    CHECK(INT_TO_SINT(4223) == 127);  // 16#107F -> 16#7F (TwinCAT's example)
    CHECK(DINT_TO_UINT(-1) == 65535u);
    CHECK(UINT_TO_INT(65535) == -1);
    CHECK(USINT_TO_SINT(200) == -56);
    CHECK(SINT_TO_LINT(-1) == -1);
    CHECK(SINT_TO_ULINT(-1) == std::numeric_limits<ULINT>::max());
    CHECK(WORD_TO_BYTE(WORD(0x1234)) == 0x34);
    CHECK(BYTE_TO_WORD(BYTE(0xAB)) == 0xAB);
    CHECK(LWORD_TO_DINT(LWORD(0x1234567880000000)) == -2147483647 - 1);
    CHECK(DINT_TO_WORD(70000) == 4464);
  }

  TEST_CASE("BOOL converts to and from 0 and 1") {
    CHECK(INT_TO_BOOL(0) == FALSE);
    CHECK(INT_TO_BOOL(-1) == TRUE);
    CHECK(BYTE_TO_BOOL(BYTE(0x80)) == TRUE);
    CHECK(BOOL_TO_INT(TRUE) == 1);
    CHECK(BOOL_TO_LWORD(FALSE) == 0u);
    CHECK(BOOL_TO_REAL(TRUE) == 1.0f);
    CHECK(LREAL_TO_BOOL(0.987654321) == TRUE);  // CODESYS's example
    CHECK(REAL_TO_BOOL(0.0f) == FALSE);
    CHECK(TIME_TO_BOOL(TIME()) == FALSE);
    CHECK(BOOL_TO_TIME(TRUE) == TIME(1));
  }

  TEST_CASE("REAL to integer rounds to nearest, halves away from zero") {
    CHECK(REAL_TO_INT(1.5f) == 2);    // CODESYS: REAL_TO_INT(1.5) = 2
    CHECK(REAL_TO_INT(1.4f) == 1);    // CODESYS: REAL_TO_INT(1.4) = 1
    CHECK(REAL_TO_INT(-1.5f) == -2);  // CODESYS: REAL_TO_INT(-1.5) = -2
    CHECK(REAL_TO_INT(2.5f) == 3);
    CHECK(REAL_TO_INT(-0.4f) == 0);
    CHECK(LREAL_TO_DINT(1.234) == 1);
    CHECK(LREAL_TO_UDINT(0.987654321) == 1u);
    CHECK(REAL_TO_BYTE(1.234f) == 1);
  }

  TEST_CASE("REAL beyond the target's range keeps the low bytes of the rounded value") {
    CHECK(REAL_TO_INT(40000.0f) == -25536);  // 40000 = 16#9C40
    CHECK(LREAL_TO_DINT(2147483648.0) == -2147483647 - 1);
    CHECK(LREAL_TO_ULINT(1.5e19) == ULINT(15000000000000000000u));
    CHECK(LREAL_TO_LINT(-1.0e300) == std::numeric_limits<LINT>::min());  // saturates, never UB
    CHECK(LREAL_TO_LINT(1.0e300) == std::numeric_limits<LINT>::max());
    CHECK(LREAL_TO_DINT(std::nan("")) == 0);
    CHECK(REAL_TO_INT(std::numeric_limits<float>::infinity()) == -1);  // low bytes of INT64_MAX
  }

  TEST_CASE("integer to REAL gives the nearest REAL") {
    CHECK(DINT_TO_REAL(16777217) == 16777216.0f);
    CHECK(INT_TO_LREAL(-5) == -5.0);
    CHECK(ULINT_TO_LREAL(ULINT(18446744073709551615u)) == 18446744073709551616.0);
    CHECK(LREAL_TO_REAL(0.1) == 0.1f);
    CHECK(REAL_TO_LREAL(0.5f) == 0.5);
  }

  TEST_CASE("TRUNC truncates toward zero") {
    CHECK(TRUNC(REAL(-1.7f)) == -1);
    CHECK(TRUNC(LREAL(2.9)) == 2);
    CHECK(TRUNC_INT(LREAL(32767.9)) == 32767);
    CHECK(TRUNC(LREAL(std::nan(""))) == 0);
  }

  TEST_CASE("TIME converts to and from numbers of milliseconds, LTIME of nanoseconds") {
    CHECK(TIME_TO_DWORD("T#5m"_iec) == 300000u);  // CODESYS: TIME_TO_DWORD(T#5m) = 300000
    CHECK(TIME_TO_SINT("T#12ms"_iec) == 12);
    CHECK(TIME_TO_INT("T#1m"_iec) == -5536);  // 60000 keeps its low 16 bits
    CHECK(DINT_TO_TIME(1500) == "T#1s500ms"_iec);
    CHECK(INT_TO_TIME(-1) == TIME::max());  // TIME is unsigned: -1 wraps
    CHECK(LTIME_TO_LINT("LTIME#1us"_iec) == 1000);
    CHECK(ULINT_TO_LTIME(ULINT(1500)) == "LTIME#1us500ns"_iec);
    CHECK(TIME_TO_REAL("T#1.5s"_iec) == 1500.0f);
    CHECK(REAL_TO_TIME(1.5f) == TIME(2));  // rounds to whole milliseconds
    CHECK(LREAL_TO_TIME(1500.4) == "T#1s500ms"_iec);
    CHECK(LREAL_TO_LTIME(2.5) == LTIME::from_ticks(3));
  }

  TEST_CASE("TIME and LTIME convert into each other") {
    CHECK(TIME_TO_LTIME("T#1s"_iec) == "LTIME#1s"_iec);
    CHECK(LTIME_TO_TIME("LTIME#1s999ms999us"_iec) == "T#1s999ms"_iec);
    CHECK(LTIME_TO_TIME("LTIME#60d"_iec) == TIME::from_ticks(static_cast<std::uint32_t>(5184000000u % 4294967296u)));
  }

  TEST_CASE("values convert to their IEC text") {
    CHECK(INT_TO_STRING(-32768) == "-32768");
    CHECK(BYTE_TO_STRING(BYTE(255)) == "255");
    CHECK(ULINT_TO_STRING(ULINT(18446744073709551615u)) == "18446744073709551615");
    CHECK(BOOL_TO_STRING(TRUE) == "TRUE");
    CHECK(TIME_TO_STRING("T#12ms"_iec) == "T#12ms");  // CODESYS's example
    CHECK(TIME_TO_STRING("T#90s"_iec) == "T#1m30s");
    CHECK(LTIME_TO_STRING("LTIME#1ms500us"_iec) == "LTIME#1ms500us");
    CHECK(REAL_TO_STRING(1.5f) == "1.5");
    CHECK(LREAL_TO_STRING(-0.25) == "-0.25");
    CHECK(convert<STRING<4>>(INT(-32768)) == "-327");  // a smaller target truncates
  }

  TEST_CASE("text converts to values, invalid text gives zero as in CODESYS") {
    CHECK(STRING_TO_INT("123") == 123);
    CHECK(STRING_TO_INT(" 42 ") == 42);  // surrounding spaces are ignored
    CHECK(STRING_TO_WORD("16#FF") == 255);
    CHECK(STRING_TO_INT("2.7") == 3);  // a REAL text rounds
    CHECK(STRING_TO_INT("abc") == 0);
    CHECK(STRING_TO_INT("99999") == 0);  // out of range: not a valid INT literal
    CHECK(STRING_TO_INT("-32768") == -32768);
    CHECK(STRING_TO_INT("40000.0") == 0);  // a REAL text outside INT, too
    CHECK(STRING_TO_INT("-32768.4") == -32768);
    CHECK(STRING_TO_USINT("255.4") == 255);
    CHECK(STRING_TO_USINT("-1") == 0);
    CHECK(STRING_TO_BOOL("TRUE") == TRUE);
    CHECK(STRING_TO_BOOL("maybe") == FALSE);
    CHECK(STRING_TO_TIME("T#1h") == "T#1h"_iec);
    CHECK(STRING_TO_TIME("5s") == TIME());  // a duration needs its prefix
    CHECK(STRING_TO_LTIME("LTIME#1us") == "LTIME#1us"_iec);
    CHECK(STRING_TO_REAL("1.5E3") == 1500.0f);
    CHECK(STRING_TO_LREAL("x") == 0.0);
    const STRING<12> text = "12345";
    CHECK(STRING_TO_DINT(text) == 12345);  // any capacity
  }

  TEST_CASE("STRING and WSTRING convert Latin-1 to UCS-2 and back") {
    CHECK(STRING_TO_WSTRING("abc") == u"abc");
    CHECK(STRING_TO_WSTRING("\xE4") == u"\u00e4");  // Latin-1 a-umlaut
    CHECK(WSTRING_TO_STRING(u"\u00e4") == "\xE4");
    CHECK(WSTRING_TO_STRING(u"\u20ac") == "?");  // the euro sign is not Latin-1
    CHECK(WSTRING_TO_INT(u"42") == 42);
    CHECK(INT_TO_WSTRING(-5) == u"-5");
    CHECK(TIME_TO_WSTRING("T#1s"_iec) == u"T#1s");
  }

  TEST_CASE("TO_<type> converts from any elementary type and from C++ values") {
    CHECK(TO_INT(REAL(2.5f)) == 3);
    CHECK(TO_DINT(1.5) == 2);
    CHECK(TO_BOOL(INT(5)) == TRUE);
    CHECK(TO_BOOL(true) == TRUE);
    CHECK(TO_STRING("T#1s"_iec) == "T#1s");
    CHECK(TO_TIME(1500) == "T#1s500ms"_iec);
    CHECK(TO_LREAL(7u) == 7.0);
    CHECK(TO_INT("17") == 17);
    CHECK(TO_WSTRING(u"x") == u"x");
  }
}
