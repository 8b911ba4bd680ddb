// What the MQTT bridge writes is valid JSON whatever a command's payload holds: a rejection
// repeats the payload's first 64 bytes, cut between characters, with bytes that begin no
// well-formed UTF-8 sequence as U+FFFD (docs/exchange.md, "Commands"). Checked here with
// exact expectations and with a strict checker over random payloads; the test
// exchange.mqtt_rejections_python hands the same messages to Python's json module.
#include "flood_payload.hpp"
#include "iecoop_test.hpp"
#include "json_check.hpp"

#include <iecoop/exchange/detail/mqtt_json.hpp>

#include <cstdint>
#include <random>
#include <string>
#include <string_view>

using iecoop::detail::mqtt_append_json_string;
using iecoop::detail::mqtt_rejection_message;
using iecoop::detail::utf8_sequence;
using iecoop_test::is_json;

namespace {

std::string json_string(std::string_view text, std::size_t max_bytes = static_cast<std::size_t>(-1)) {
  std::string out;
  mqtt_append_json_string(out, text, max_bytes);
  return out;
}

}  // namespace

TEST_SUITE("MQTT bridge: JSON") {
  TEST_CASE("well-formed UTF-8 sequences are told from the rest (RFC 3629)") {
    CHECK(utf8_sequence("a", 0) == 1);
    CHECK(utf8_sequence("\xC3\xA4", 0) == 2);          // ä
    CHECK(utf8_sequence("\xE2\x82\xAC", 0) == 3);      // €
    CHECK(utf8_sequence("\xF0\x9F\x98\x80", 0) == 4);  // U+1F600
    CHECK(utf8_sequence("\xB0", 0) == 0);              // a continuation byte alone (Latin-1 °)
    CHECK(utf8_sequence("\xC0\xAF", 0) == 0);          // overlong '/'
    CHECK(utf8_sequence("\xE0\x80\xAF", 0) == 0);      // overlong
    CHECK(utf8_sequence("\xED\xA0\x80", 0) == 0);      // a surrogate
    CHECK(utf8_sequence("\xF4\x90\x80\x80", 0) == 0);  // above U+10FFFF
    CHECK(utf8_sequence("\xE2\x82", 0) == 0);          // cut
    CHECK(utf8_sequence("\xFF", 0) == 0);
    CHECK(utf8_sequence("", 0) == 0);
  }

  TEST_CASE("a JSON string: escapes, UTF-8 kept, other bytes replaced, a cut between characters") {
    CHECK(json_string("plain") == "\"plain\"");
    CHECK(json_string("a\"b\\c") == "\"a\\\"b\\\\c\"");
    CHECK(json_string(std::string_view("\x01\n\x1F\x7F", 4)) == "\"\\u0001\\u000a\\u001f\x7F\"");
    CHECK(json_string("Gr\xC3\xBC\xC3\x9F \xE2\x82\xAC") == "\"Gr\xC3\xBC\xC3\x9F \xE2\x82\xAC\"");  // kept as is
    CHECK(json_string("25\xB0"
                      "C") == "\"25\\ufffdC\"");             // Latin-1 °
    CHECK(json_string("\xE2\x82") == "\"\\ufffd\\ufffd\"");  // a cut sequence
    CHECK(json_string(std::string_view("a\0b", 3)) == "\"a\\u0000b\"");
    // At most max_bytes bytes, never part of a character: "€" (3 bytes) does not fit in 2.
    CHECK(json_string("ab\xE2\x82\xAC", 4) == "\"ab\"");
    CHECK(json_string("ab\xE2\x82\xAC", 5) == "\"ab\xE2\x82\xAC\"");
    CHECK(json_string("abc", 0) == "\"\"");
  }

  TEST_CASE("a rejection message is valid JSON and repeats the payload's first 64 bytes") {
    std::string message;
    mqtt_rejection_message(message, "not a value of the type", "INT", "70000");
    CHECK(message == R"({"reason":"not a value of the type","type":"INT","payload":"70000"})");
    CHECK(is_json(message));
    // 63 ASCII bytes and a 2-byte character across the 64th: the character is left out whole.
    const std::string long_payload = std::string(63, 'x') + "\xC3\xA4" + "yyyy";
    mqtt_rejection_message(message, "r", "", long_payload);
    CHECK(message == "{\"reason\":\"r\",\"payload\":\"" + std::string(63, 'x') + "\"}");
    CHECK(is_json(message));
  }

  TEST_CASE("random payloads, a flood's worth: every rejection message is valid JSON") {
    const std::uint64_t seed = std::random_device()();
    CAPTURE(seed);
    std::mt19937_64 random(seed);
    std::string message;
    for (int n = 0; n < 20'000; ++n) {
      const std::string payload = iecoop_test::flood_payload(random);
      mqtt_rejection_message(message, "a reason with \"quotes\"", "STRING(80)", payload);
      iecoop_test::json_checker checker;
      CAPTURE(payload);
      CAPTURE(message);
      REQUIRE(checker.check(message));
    }
  }

  TEST_CASE("the checker itself refuses what is no JSON") {
    CHECK(is_json(R"({"a":[1,-2.5e3,true,null,"x\u00e4\ud83d\ude00"]})"));
    CHECK_FALSE(is_json("{\"a\":\"\xB0\"}"));  // invalid UTF-8 in a string
    CHECK_FALSE(is_json("{\"a\":\"\x01\"}"));  // a raw control character
    CHECK_FALSE(is_json(R"({"a":1,})"));
    CHECK_FALSE(is_json(R"({"a":01})"));
    CHECK_FALSE(is_json(R"("\ud800")"));  // a lone surrogate
    CHECK_FALSE(is_json(R"("\x")"));
    CHECK_FALSE(is_json(R"({"a":1} x)"));
    CHECK_FALSE(is_json(R"("open)"));
  }
}
