// <iecoop/fmt.hpp>: fmt prints IEC values as ST writes them, and keeps fmt's format specs.
#include "iecoop_test.hpp"

#include <iecoop/fmt.hpp>

#include <fmt/format.h>

using namespace iecoop;

TEST_SUITE("fmt") {
  TEST_CASE("TIME, LTIME and BOOL print in their IEC form") {
    CHECK(fmt::format("{}", "T#1s500ms"_iec) == "T#1s500ms");
    CHECK(fmt::format("{}", TIME()) == "T#0ms");
    CHECK(fmt::format("{}", "LTIME#1ms500us"_iec) == "LTIME#1ms500us");
    CHECK(fmt::format("{} {}", TRUE, FALSE) == "TRUE FALSE");
  }

  TEST_CASE("STRING and WSTRING print their text, WSTRING as UTF-8") {
    CHECK(fmt::format("{}", STRING<12>("conveyor belt one")) == "conveyor bel");
    CHECK(fmt::format("{}", WSTRING<>(u"gr\u00fc\u00df \u20ac")) == "gr\xC3\xBC\xC3\x9F \xE2\x82\xAC");
    CHECK(fmt::format("[{:>6}]", STRING<>("ab")) == "[    ab]");
  }

  TEST_CASE("integers and REALs keep fmt's number formatting") {
    CHECK(fmt::format("{}", INT(-32768)) == "-32768");
    CHECK(fmt::format("{:04x}", WORD(255)) == "00ff");
    CHECK(fmt::format("{}", SINT(-5)) == "-5");  // a number, not a character
    CHECK(fmt::format("{}", BYTE(65)) == "65");
    CHECK(fmt::format("{:.2f}", REAL(1.5f)) == "1.50");
    CHECK(fmt::format("{}", LREAL(0.1)) == "0.1");
    CHECK(fmt::format("[{:>10}]", "T#1s"_iec) == "[      T#1s]");
  }

  TEST_CASE("a block's variables and properties print as their values") {
    struct FB_Shown : function_block<FB_Shown> {
      var<TIME> tElapsed{"T#1s500ms"_iec};
      INT iLevel = 42;
      INT Level_Get() const { return iLevel; }
      [[no_unique_address]] property<INT, &FB_Shown::Level_Get> Level{this};
      void body() {}
    };
    FB_Shown fb;
    CHECK(fmt::format("{} {:>4}", fb.tElapsed, fb.Level) == "T#1s500ms   42");
    output<BOOL> out{TRUE};
    CHECK(fmt::format("{}", out) == "TRUE");
  }
}
