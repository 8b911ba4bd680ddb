// Prints the MQTT bridge's rejection message for many random payloads (the bytes of a command
// flood: any byte, pieces of UTF-8, JSON's own characters), one per line, for the test
// exchange.mqtt_rejections_python, which parses each with Python's json module: a JSON parser
// nobody here wrote. The seed is the first argument (else a random one), printed to stderr.
#include "flood_payload.hpp"

#include <iecoop/exchange/detail/mqtt_json.hpp>

#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <random>
#include <string>

int main(int argc, char** argv) {
  const std::uint64_t seed = argc > 1 ? std::strtoull(argv[1], nullptr, 10) : std::random_device()();
  std::fprintf(stderr, "mqtt_rejections: seed %llu\n", static_cast<unsigned long long>(seed));
  std::mt19937_64 random(seed);
  std::string message;
  for (int n = 0; n < 20'000; ++n) {
    const std::string payload = iecoop_test::flood_payload(random);
    iecoop::detail::mqtt_rejection_message(message, "not a value of the type", "STRING(80)", payload);
    std::fwrite(message.data(), 1, message.size(), stdout);
    std::fputc('\n', stdout);
  }
  return 0;
}
