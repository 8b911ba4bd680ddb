// Fuzz target: an MQTT command's payload, as a flood sends it, through the bridge's command path
// (the literal found in the payload: bare, a JSON string, {"value": ...}; then parsed as BOOL,
// INT, UDINT, REAL, TIME) and, wherever it is refused, the `/set/rejected` message the bridge
// publishes. Every such message must be valid JSON (a strict checker: RFC 8259 with UTF-8 per
// RFC 3629), repeat at most 64 bytes of the payload, and never cut a character.
#include "fuzz_check.hpp"
#include "json_check.hpp"

#include <iecoop/exchange/detail/mqtt_commands.hpp>
#include <iecoop/exchange/detail/mqtt_json.hpp>

#include <cstddef>
#include <cstdint>
#include <string>
#include <string_view>

namespace {

using namespace iecoop;
using iecoop_fuzz::require;

void check_message(std::string_view reason, std::string_view type, std::string_view payload) {
  std::string message;
  detail::mqtt_rejection_message(message, reason, type, payload);
  iecoop_test::json_checker checker;
  require(checker.check(message), "a rejection message is valid JSON", message);
  // The payload's part: a prefix of at most 64 bytes, ending between two characters.
  std::string alone;
  detail::mqtt_append_json_string(alone, payload, detail::mqtt_rejected_payload_bytes);
  require(message.ends_with(alone + "}"), "the message ends with the payload's JSON string", message);
}

template <class T>
void parse_as(std::string_view text, std::string_view type, std::string_view payload) {
  T value{};
  if (const char* reason = detail::mqtt_parse(text, value)) check_message(reason, type, payload);
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string_view payload = iecoop_fuzz::as_text(data, size);
  check_message("a reason", "", payload);
  char buffer[detail::mqtt_max_payload];
  const detail::mqtt_literal literal = detail::mqtt_command_literal(payload, buffer, sizeof buffer);
  if (literal.error != nullptr) {
    check_message(literal.error, "INT", payload);
    return 0;
  }
  parse_as<BOOL>(literal.text, "BOOL", payload);
  parse_as<INT>(literal.text, "INT", payload);
  parse_as<UDINT>(literal.text, "UDINT", payload);
  parse_as<REAL>(literal.text, "REAL", payload);
  parse_as<TIME>(literal.text, "TIME", payload);
  return 0;
}
