// A command payload as a flood sends it, for the tests of what the MQTT bridge publishes about
// such payloads (tests/unit/mqtt_json_test.cpp, tests/programs/mqtt_rejections.cpp): up to 119
// bytes of any byte, pieces of UTF-8 (whole, cut, overlong, a surrogate), JSON's own characters
// and IEC literals.
#pragma once

#include <cstddef>
#include <iterator>
#include <random>
#include <string>
#include <string_view>

namespace iecoop_test {

inline std::string flood_payload(std::mt19937_64& random) {
  static constexpr std::string_view pieces[] = {
      "\xC3", "\xA4", "\xE2\x82\xAC", "\xF0\x9F\x98", "\x80", "\xFF", "\"",    "\\",           "\\u",     "{",
      "}",    "\x01", "\n",           "\r",           "\x7F", "T#2s", "16#FF", "\xED\xA0\x80", "\xC0\xAF"};
  std::string payload;
  const std::size_t length = random() % 120;
  while (payload.size() < length) {
    if (random() % 2 == 0) {
      payload += static_cast<char>(random() % 256);
    } else {
      payload += pieces[random() % std::size(pieces)];
    }
  }
  return payload;
}

}  // namespace iecoop_test
