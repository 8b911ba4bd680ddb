// Fuzz target: direct addresses as text (parse_address: %IX0.5, %QW2, %MD48). Checks, for any input:
//   - a failed parse names its error at a position within the text;
//   - what parses is an address of the documented shape: a bit below 8 (0 for a wide address),
//     a number up to max_address_number, whose bytes lie within 32 bits in either addressing;
//   - the address written canonically (%<area><size><number>[.<bit>]) parses back to the same
//     address, and so does its bit written as IEC's flat bit number (%IX75);
//   - letters in either case mean the same address.
#include "fuzz_check.hpp"

#include <cstddef>
#include <cstdint>
#include <string>
#include <string_view>

namespace {

using namespace iecoop;
using iecoop_fuzz::require;

std::string canonical(const io_address& a) {
  std::string text = "%";
  text += a.area == io_area::input ? 'I' : a.area == io_area::output ? 'Q' : 'M';
  switch (a.width) {
    case io_width::bit: text += 'X'; break;
    case io_width::byte: text += 'B'; break;
    case io_width::word: text += 'W'; break;
    case io_width::dword: text += 'D'; break;
    case io_width::lword: text += 'L'; break;
  }
  text += std::to_string(a.number);
  if (a.width == io_width::bit) {
    text += '.';
    text += std::to_string(a.bit);
  }
  return text;
}

std::string lower(std::string_view text) {
  std::string result(text);
  for (char& c : result) {
    if (c >= 'A' && c <= 'Z') c = static_cast<char>(c - 'A' + 'a');
  }
  return result;
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string_view text = iecoop_fuzz::as_text(data, size);
  const address_parse parsed = parse_address(text);
  iecoop_fuzz::require_error_in_text(parsed, text);
  const address_parse lowered = parse_address(lower(text));
  require(lowered.has_value() == parsed.has_value() && lowered.error() == parsed.error() &&
              lowered.position() == parsed.position(),
          "an address's letters mean the same in either case", text);
  if (!parsed) return 0;
  const io_address a = parsed.value_or(io_address{});
  require(lowered.value_or(io_address{}) == a, "an address's letters mean the same in either case", text);
  require(a.bit < 8, "a bit address names a bit 0..7", text);
  require(a.width == io_width::bit || a.bit == 0, "a wide address names no bit", text);
  require(a.number <= max_address_number, "an address's number is at most max_address_number", text);
  for (const addressing mode : {addressing::codesys, addressing::byte_offset}) {
    const std::uint64_t end = std::uint64_t{a.first_byte(mode)} + a.byte_count();
    require(end <= std::uint64_t{1} << 32, "an address's bytes lie within 32 bits", text);
    require(a.first_bit(mode) == std::uint64_t{a.first_byte(mode)} * 8 + a.bit, "first_bit is first_byte's bit", text);
  }
  const std::string written = canonical(a);
  const address_parse back = parse_address(written);
  require(back.has_value() && back.value_or(io_address{}) == a, "an address written canonically parses back", written);
  if (a.width == io_width::bit && std::uint64_t{a.number} * 8 + a.bit <= max_address_number) {
    std::string flat = written.substr(0, 3) + std::to_string(std::uint64_t{a.number} * 8 + a.bit);
    const address_parse flat_back = parse_address(flat);
    require(flat_back.has_value() && flat_back.value_or(io_address{}) == a, "a bit's flat number parses back", flat);
  }
  return 0;
}
