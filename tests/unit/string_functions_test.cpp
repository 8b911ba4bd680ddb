// The IEC string functions with 1-based positions: the documented examples of the CODESYS
// Standard library, result capacities, and every out-of-range argument.
#include "iecoop_test.hpp"

#include <type_traits>

using namespace iecoop;

// Results are big enough for every possible result.
static_assert(std::is_same_v<decltype(LEFT(STRING<20>(), 3)), STRING<20>>);
static_assert(std::is_same_v<decltype(CONCAT(STRING<20>(), STRING<30>())), STRING<50>>);
static_assert(std::is_same_v<decltype(CONCAT(STRING<2>(), "abc", STRING<1>())), STRING<6>>);
static_assert(std::is_same_v<decltype(INSERT(STRING<10>(), STRING<5>(), 1)), STRING<15>>);
static_assert(std::is_same_v<decltype(REPLACE(STRING<10>(), "xy", 1, 1)), STRING<12>>);
static_assert(std::is_same_v<decltype(DELETE(STRING<10>(), 1, 1)), STRING<10>>);
static_assert(std::is_same_v<decltype(MID(WSTRING<7>(), 1, 1)), WSTRING<7>>);
static_assert(std::is_same_v<decltype(LEN(STRING<>())), INT> && std::is_same_v<decltype(FIND("a", "b")), INT>);
static_assert(std::is_same_v<decltype(CONCAT("", "")), STRING<1>>);  // no STRING(0): the smallest is STRING(1)
template <class P>
concept position_accepted = requires(P p) { LEFT("SUSI", p); };

// Everything is constexpr.
static_assert(CONCAT(LEFT("SUSI", 2), MID("SUSI", 2, 3)) == "SUSI");

TEST_SUITE("string functions") {
  TEST_CASE("LEN counts characters") {
    CHECK(LEN("SUSI") == 4);
    CHECK(LEN(STRING<>()) == 0);
    CHECK(LEN(STRING<12>("conveyor belt one")) == 12);
    CHECK(LEN(WSTRING<>(u"\u00fc\u00df")) == 2);
  }

  TEST_CASE("LEFT and RIGHT, including lengths outside the string") {
    CHECK(LEFT("SUSI", 3) == "SUS");   // CODESYS: LEFT('SUSI', 3) = 'SUS'
    CHECK(RIGHT("SUSI", 3) == "USI");  // CODESYS: RIGHT('SUSI', 3) = 'USI'
    CHECK(LEFT("SUSI", 4) == "SUSI");
    CHECK(LEFT("SUSI", 10) == "SUSI");  // longer than the string: all of it
    CHECK(RIGHT("SUSI", 10) == "SUSI");
    CHECK(LEFT("SUSI", 0) == "");
    CHECK(RIGHT("SUSI", 0) == "");
    CHECK(LEFT("SUSI", -3) == "");  // negative: empty
    CHECK(RIGHT("SUSI", INT(-1)) == "");
    CHECK(LEFT(STRING<>(), 3) == "");
    CHECK(LEFT("SUSI", ULINT(18446744073709551615u)) == "SUSI");
  }

  TEST_CASE("MID with positions and lengths in and out of range") {
    CHECK(MID("SUSI", 2, 2) == "US");  // CODESYS: MID('SUSI', 2, 2) = 'US'
    CHECK(MID("SUSI", 1, 1) == "S");
    CHECK(MID("SUSI", 4, 1) == "SUSI");
    CHECK(MID("SUSI", 10, 3) == "SI");  // past the end: what is there
    CHECK(MID("SUSI", 2, 4) == "I");
    CHECK(MID("SUSI", 2, 5) == "");  // position beyond the string
    CHECK(MID("SUSI", 2, 0) == "");  // position 0: there is no character 0
    CHECK(MID("SUSI", 2, -1) == "");
    CHECK(MID("SUSI", 0, 1) == "");
    CHECK(MID("SUSI", -2, 1) == "");
    CHECK(MID(STRING<>(), 1, 1) == "");
    // "A better life. A better world.": 15 characters from position 16.
    CHECK(MID(STRING<32>("A better life. A better world."), 15, 16) == "A better world.");
  }

  TEST_CASE("CONCAT joins two or more strings") {
    CHECK(CONCAT("SUSI", "WILLI") == "SUSIWILLI");  // CODESYS: CONCAT('SUSI', 'WILLI')
    CHECK(CONCAT("a", "b", "c", "d") == "abcd");
    CHECK(CONCAT(STRING<>(), STRING<>()) == "");
    CHECK(CONCAT(WSTRING<3>(u"ab"), u"c") == u"abc");
    const STRING<5> full = "12345";
    const STRING<5> more = "67890";
    STRING<8> target = CONCAT(full, more);  // the result holds 10; the target keeps 8
    CHECK(target == "12345678");
  }

  TEST_CASE("INSERT after a position, including positions outside the string") {
    CHECK(INSERT("SUSI", "XY", 2) == "SUXYSI");  // CODESYS: INSERT('SUSI', 'XY', 2)
    CHECK(INSERT("SUSI", "XY", 0) == "XYSUSI");  // 0: before the first character
    CHECK(INSERT("SUSI", "XY", 4) == "SUSIXY");  // after the last character
    CHECK(INSERT("SUSI", "XY", 5) == "SUSI");    // beyond the string: unchanged
    CHECK(INSERT("SUSI", "XY", -1) == "SUSI");   // negative: unchanged (CODESYS)
    CHECK(INSERT("", "XY", 0) == "XY");
    CHECK(INSERT("SUSI", "", 2) == "SUSI");
  }

  TEST_CASE("DELETE, including positions and lengths outside the string") {
    CHECK(DELETE("SUXYSI", 2, 3) == "SUSI");  // CODESYS: DELETE('SUXYSI', 2, 3)
    CHECK(DELETE("SUXYSI", 1, 1) == "UXYSI");
    CHECK(DELETE("SUXYSI", 10, 3) == "SU");  // longer than what is left: to the end
    CHECK(DELETE("SUXYSI", 1, 6) == "SUXYS");
    CHECK(DELETE("SUXYSI", 1, 7) == "SUXYSI");  // beyond the string: unchanged
    CHECK(DELETE("SUXYSI", 1, 0) == "SUXYSI");
    CHECK(DELETE("SUXYSI", 0, 2) == "SUXYSI");  // nothing to delete
    CHECK(DELETE("SUXYSI", -1, 2) == "SUXYSI");
    CHECK(DELETE("", 1, 1) == "");
  }

  TEST_CASE("REPLACE, including positions and lengths outside the string") {
    CHECK(REPLACE("SUXYSI", "K", 2, 3) == "SUKSI");  // CODESYS: REPLACE('SUXYSI', 'K', 2, 3)
    CHECK(REPLACE("SUSI", "XY", 0, 3) == "SUXYSI");  // L = 0: an insertion before P
    CHECK(REPLACE("SUSI", "XY", 10, 2) == "SXY");    // to the end
    CHECK(REPLACE("SUSI", "XY", 1, 5) == "SUSIXY");  // P = LEN + 1: appends
    CHECK(REPLACE("SUSI", "XY", 1, 6) == "SUSI");    // beyond: unchanged
    CHECK(REPLACE("SUSI", "XY", 1, 0) == "SUSI");
    CHECK(REPLACE("SUSI", "XY", -1, 1) == "SUSI");
    CHECK(REPLACE("SUSI", "", 2, 2) == "SI");
  }

  TEST_CASE("FIND gives the 1-based position of the first occurrence, or 0") {
    CHECK(FIND("SUXYSI", "XY") == 3);  // CODESYS: FIND('SUXYSI', 'XY') = 3
    CHECK(FIND("SUSI", "S") == 1);
    CHECK(FIND("SUSI", "SI") == 3);
    CHECK(FIND("SUSI", "X") == 0);
    CHECK(FIND("SUSI", "SUSIS") == 0);
    CHECK(FIND("SUSI", "") == 0);
    CHECK(FIND("", "S") == 0);
    CHECK(FIND(WSTRING<>(u"\u00e4b\u00e4c"), u"\u00e4c") == 3);
  }

  TEST_CASE("positions may be any IEC integer or a C++ integer") {
    CHECK(MID("SUSI", INT(2), DINT(2)) == "US");
    CHECK(LEFT("SUSI", USINT(2)) == "SU");
    CHECK(DELETE("SUSI", LINT(1), UINT(1)) == "USI");
    static_assert(!position_accepted<BYTE> && !position_accepted<BOOL> && !position_accepted<REAL>);  // IEC: ANY_INT
    static_assert(position_accepted<SINT> && position_accepted<ULINT> && position_accepted<long>);
    CHECK(RIGHT("SUSI", 2u) == "SI");
  }
}
