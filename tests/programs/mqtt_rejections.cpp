// Prints the MQTT bridge's rejection message for many random payloads (the bytes of a command
// flood: any byte, pieces of UTF-8, JSON's own characters), one per line, for the test
// exchange.mqtt_rejections_python, which parses each with Python's json module: a JSON parser
// nobody here wrote. The seed is the first argument (else a random one), printed to stderr.
#include <iecoop/exchange/detail/mqtt_json.hpp>

#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <random>
#include <string>
#include <string_view>

int main(int argc, char** argv) {
  const std::uint64_t seed = argc > 1 ? std::strtoull(argv[1], nullptr, 10) : std::random_device()();
  std::fprintf(stderr, "mqtt_rejections: seed %llu\n", static_cast<unsigned long long>(seed));
  std::mt19937_64 random(seed);
  const std::string_view pieces[] = {
      "\xC3", "\xA4", "\xE2\x82\xAC", "\xF0\x9F\x98", "\x80", "\xFF", "\"",           "\\",      "\\u",
      "{",    "}",    "\x01",         "\n",           "\r",   "\x7F", "\xED\xA0\x80", "\xC0\xAF"};
  std::string payload;
  std::string message;
  for (int n = 0; n < 20'000; ++n) {
    payload.clear();
    const std::size_t length = random() % 120;
    while (payload.size() < length) {
      if (random() % 2 == 0) {
        payload += static_cast<char>(random() % 256);
      } else {
        payload += pieces[random() % std::size(pieces)];
      }
    }
    iecoop::detail::mqtt_rejection_message(message, "not a value of the type", "STRING(80)", payload);
    std::fwrite(message.data(), 1, message.size(), stdout);
    std::fputc('\n', stdout);
  }
  return 0;
}
