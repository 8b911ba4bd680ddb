// "..."_iec: IEC literals written as in ST, with the type picked by the prefix and every
// value checked at compile time. (Invalid literals are compile-fail tests.)
#include "iecoop_test.hpp"

#include <type_traits>

using namespace iecoop;

// The literal forms of the issue and of CODESYS's TIME page, checked while compiling.
static_assert("T#1h2m3s4ms"_iec.count() == 3723004);
static_assert("TIME#5s"_iec.count() == 5000);
static_assert("t#1.5s"_iec.count() == 1500);
static_assert("T#100s12ms"_iec.count() == 100012);
static_assert("LTIME#1ms500us"_iec.count() == 1500000);
static_assert("T#1_000ms"_iec.count() == 1000);
static_assert("t#12h4m34ms"_iec.count() == 43440034);
static_assert("LT#1000d15h23m12s34ms2us44ns"_iec.count() == 86455392034002044);

// The prefix picks the type.
static_assert(std::is_same_v<decltype("T#5s"_iec), TIME>);
static_assert(std::is_same_v<decltype("LTIME#5s"_iec), LTIME>);
static_assert(std::is_same_v<decltype("INT#5"_iec), INT>);
static_assert(std::is_same_v<decltype("WORD#16#FF"_iec), WORD>);
static_assert(std::is_same_v<decltype("ULINT#1"_iec), ULINT>);
static_assert(std::is_same_v<decltype("TRUE"_iec), BOOL>);
static_assert(std::is_same_v<decltype("BOOL#0"_iec), BOOL>);

static_assert("INT#-32768"_iec == -32768);
static_assert("INT#16#FFFF"_iec == -1);
static_assert("DINT#16#A1"_iec == 161);
static_assert("BYTE#2#1001_0011"_iec == 0x93);
static_assert("UDINT#4294967295"_iec == 4294967295u);
static_assert("SINT#8#177"_iec == 127);
static_assert("TRUE"_iec == TRUE && "FALSE"_iec == FALSE && "BOOL#1"_iec == TRUE);

TEST_SUITE("IEC literals") {
  TEST_CASE("literals are values usable anywhere a TIME is") {
    TIME pt = "T#300ms"_iec;
    pt += "T#1s"_iec;
    CHECK(pt == "T#1s300ms"_iec);
    const LTIME fine = "LTIME#1ms500us"_iec;
    CHECK(fine > pt / 1000);
    CHECK("T#0ms"_iec == TIME());
  }

  TEST_CASE("a literal has the same value as parsing the same text at run time") {
    CHECK("T#5d14h12m18s3ms"_iec == parse_time("T#5d14h12m18s3ms").value());
    CHECK("LTIME#213503d23h34m33s709ms551us615ns"_iec == LTIME::max());
    CHECK("T#49d17h2m47s295ms"_iec == TIME::max());
  }
}
