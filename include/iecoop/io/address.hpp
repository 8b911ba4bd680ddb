// SPDX-License-Identifier: MIT
// iecoop/io/address.hpp — IEC 61131-3 direct addresses (%IX0.5, %QW2, %MD48), parsed and
// checked at compile time.
//
// An address names a place in the process image (see <iecoop/io/process_image.hpp>):
//
//     %  I | Q | M  [X | B | W | D | L]  number [.bit]
//        area        size (none = bit)
//
//     address_of<"%IX0.5">   // input, bit 5 of byte 0  (also "%I0.5")
//     address_of<"%IX75">    // input bit 75 (IEC's flat bit number): bit 3 of byte 9
//     address_of<"%QB7">     // output byte 7
//     address_of<"%IW2">     // input word 2: bytes 4..5 in CODESYS addressing
//     address_of<"%MD48">    // memory double word 48: bytes 192..195 (CODESYS) or 48..51 (byte_offset)
//
// The number of a B/W/D/L address counts units of its size in CODESYS ("%IW5 always
// addresses word 5"), and counts bytes in TwinCAT's byte_offset addressing. A malformed
// address does not compile; the static_assert that stops it says what is wrong. For text
// known only at run time, parse_address() returns the error instead.
#pragma once

#include <cstddef>
#include <cstdint>
#include <string_view>

#include <iecoop/config.hpp>
#include <iecoop/detail/diagnostics.hpp>
#include <iecoop/detail/fixed_string.hpp>
#include <iecoop/detail/parse_result.hpp>

#include <iecoop/detail/push_macros.hpp>

namespace iecoop {

/// The area of the process image an address lies in.
enum class io_area : std::uint8_t {
  input,   ///< %I: the inputs, latched from the field at the start of each task cycle
  output,  ///< %Q: the outputs, sent to the field at the end of each task cycle
  memory,  ///< %M: flags (marker memory), not connected to the field
};

/// The size of the value at an address.
enum class io_width : std::uint8_t {
  bit,    ///< X, or no size letter: one bit, %IX<byte>.<bit> or %IX<bit number>
  byte,   ///< B: 8 bits
  word,   ///< W: 16 bits
  dword,  ///< D: 32 bits
  lword,  ///< L: 64 bits
};

/// How the number of a B/W/D/L address maps to bytes.
enum class addressing : std::uint8_t {
  /// CODESYS (default): the number counts units of the size: %IB5 = byte 5, %IW5 = bytes
  /// 10..11, %ID5 = bytes 20..23, %IL5 = bytes 40..47. Bits: %IX5.5 = bit 5 of byte 5.
  codesys,
  /// TwinCAT: the number is the byte offset whatever the size: %MD48 = bytes 48..51.
  byte_offset,
};

/// The number of bytes of a value of width `w` (a bit lies in one byte).
constexpr std::uint32_t bytes_of(io_width w) noexcept {
  switch (w) {
    case io_width::bit:
    case io_width::byte: return 1;
    case io_width::word: return 2;
    case io_width::dword: return 4;
    case io_width::lword: return 8;
  }
  return 1;
}

/// A direct address: area, size, number and (for bit addresses) bit.
struct io_address {
  io_area area = io_area::input;
  io_width width = io_width::bit;
  std::uint32_t number = 0;  ///< the byte of a bit address; the unit (CODESYS) or byte offset (byte_offset) otherwise
  std::uint8_t bit = 0;      ///< 0..7, for bit addresses; 0 otherwise

  /// The number of bytes the value occupies (1 for a bit: the byte it lies in).
  [[nodiscard]] constexpr std::uint32_t byte_count() const noexcept { return bytes_of(width); }
  /// The first byte of the value, from the start of its area.
  [[nodiscard]] constexpr std::uint32_t first_byte(addressing mode) const noexcept {
    if (width == io_width::bit || mode == addressing::byte_offset) return number;
    return number * byte_count();
  }
  /// The first bit of the value, from bit 0 of byte 0 of its area (bit b of byte n is n * 8 + b).
  [[nodiscard]] constexpr std::uint64_t first_bit(addressing mode) const noexcept {
    return std::uint64_t{first_byte(mode)} * 8u + bit;
  }
  /// The number of bits the value occupies: 1 for a bit address, 8 per byte otherwise.
  [[nodiscard]] constexpr std::uint32_t bit_count() const noexcept {
    return width == io_width::bit ? 1u : byte_count() * 8u;
  }
  /// TRUE if both addresses lie in the same area and share at least one bit. (Two bits of
  /// the same byte do not overlap.)
  [[nodiscard]] constexpr bool overlaps(const io_address& other, addressing mode) const noexcept {
    return area == other.area && first_bit(mode) < other.first_bit(mode) + other.bit_count() &&
           other.first_bit(mode) < first_bit(mode) + bit_count();
  }

  friend constexpr bool operator==(const io_address&, const io_address&) noexcept = default;
};

/// Why a text is not a direct address.
enum class address_error {
  none,
  empty,                ///< ""
  missing_percent,      ///< "IX0.0"
  bad_area,             ///< "%AX0.0"
  incomplete,           ///< "%I*"
  bad_size,             ///< "%IZ0"
  expected_number,      ///< "%IX", "%IX0."
  number_too_large,     ///< more than 268435455
  bit_on_wide_address,  ///< "%IB2.4"
  bit_out_of_range,     ///< "%IX0.8"
  hierarchical,         ///< "%IW2.5.7.1"
  trailing_characters,  ///< "%IW2x"
};

/// The result of parse_address(): the address, or why there is none and at which character.
using address_parse = basic_parse_result<io_address, address_error>;

/// The largest number an address may have: every byte range then fits 32 bits.
inline constexpr std::uint32_t max_address_number = 0x0FFF'FFFF;

/// Parses a direct address ("%IX0.5", "%QW2", "%MD48"; letters in either case). Usable at
/// compile time and at run time.
constexpr address_parse parse_address(std::string_view text) noexcept {
  std::size_t i = 0;
  const auto fail = [&i](address_error e) { return address_parse{e, i}; };
  const auto upper = [](char c) { return (c >= 'a' && c <= 'z') ? static_cast<char>(c - 'a' + 'A') : c; };
  const auto digit = [](char c) { return c >= '0' && c <= '9'; };
  if (text.empty()) return fail(address_error::empty);
  if (text[0] != '%') return fail(address_error::missing_percent);
  i = 1;
  io_address a{};
  if (i == text.size()) return fail(address_error::bad_area);
  switch (upper(text[i])) {
    case 'I': a.area = io_area::input; break;
    case 'Q': a.area = io_area::output; break;
    case 'M': a.area = io_area::memory; break;
    default: return fail(address_error::bad_area);
  }
  ++i;
  if (i < text.size() && text[i] == '*') return fail(address_error::incomplete);
  if (i < text.size() && !digit(text[i])) {
    switch (upper(text[i])) {
      case 'X': a.width = io_width::bit; break;
      case 'B': a.width = io_width::byte; break;
      case 'W': a.width = io_width::word; break;
      case 'D': a.width = io_width::dword; break;
      case 'L': a.width = io_width::lword; break;
      default: {
        const char c = upper(text[i]);
        return fail(c >= 'A' && c <= 'Z' ? address_error::bad_size : address_error::expected_number);
      }
    }
    ++i;
    if (i < text.size() && text[i] == '*') return fail(address_error::incomplete);
  } else {
    a.width = io_width::bit;  // no size letter: a bit, as %IX
  }

  // A decimal number; false if there is none or it is too large.
  address_error number_error = address_error::none;
  const auto number = [&](std::uint32_t& out) {
    if (i == text.size() || !digit(text[i])) {
      number_error = address_error::expected_number;
      return false;
    }
    std::uint64_t n = 0;
    while (i < text.size() && digit(text[i])) {
      n = n * 10u + static_cast<std::uint64_t>(text[i] - '0');
      if (n > max_address_number) {
        number_error = address_error::number_too_large;
        return false;
      }
      ++i;
    }
    out = static_cast<std::uint32_t>(n);
    return true;
  };

  if (!number(a.number)) return fail(number_error);
  if (i < text.size() && text[i] == '.') {
    ++i;
    std::uint32_t bit = 0;
    if (!number(bit))
      return fail(number_error == address_error::number_too_large ? address_error::bit_out_of_range : number_error);
    if (i < text.size() && text[i] == '.') return fail(address_error::hierarchical);
    if (a.width != io_width::bit) return fail(address_error::bit_on_wide_address);
    if (bit > 7) return fail(address_error::bit_out_of_range);
    a.bit = static_cast<std::uint8_t>(bit);
  } else if (a.width == io_width::bit) {
    // No byte.bit: IEC's flat bit number, %IX75 = bit 75 of the area = bit 3 of byte 9.
    a.bit = static_cast<std::uint8_t>(a.number % 8U);
    a.number /= 8U;
  }
  if (i != text.size()) return fail(address_error::trailing_characters);
  return a;
}

namespace detail {

/// One static_assert per parse error, so the compiler prints the one that applies.
template <address_error E>
consteval void check_address() noexcept {
  static_assert(E != address_error::empty, "iecoop: empty direct address; write e.g. \"%IX0.0\", \"%QW2\" or \"%MD4\"");
  static_assert(E != address_error::missing_percent,
                "iecoop: a direct address starts with %; write e.g. \"%IX0.5\", not \"IX0.5\"");
  static_assert(E != address_error::bad_area,
                "iecoop: the area of a direct address is I (input), Q (output) or M (memory); write e.g. \"%IX0.0\", "
                "\"%QB1\" or \"%MW2\"");
  static_assert(E != address_error::incomplete,
                "iecoop: incomplete addresses (%I*, %Q*) are mapped by a device configuration, which iecoop does not "
                "have; write the full address, e.g. \"%IX0.0\"");
  static_assert(E != address_error::bad_size,
                "iecoop: unknown size letter in the direct address; the sizes are X (bit), B (byte), W (word), D "
                "(double word) and L (long word)");
  static_assert(E != address_error::expected_number,
                "iecoop: a number is missing in the direct address; write e.g. \"%IW2\" or \"%IX0.5\"");
  static_assert(E != address_error::number_too_large,
                "iecoop: the number of the direct address is too large (at most 268435455); use a smaller address");
  static_assert(E != address_error::bit_on_wide_address,
                "iecoop: only bit addresses (%IX, or %I without size) take a bit number; write \"%IX2.4\" for bit 4 of "
                "byte 2, or read the byte or word through the process image");
  static_assert(E != address_error::bit_out_of_range,
                "iecoop: the bit number of a direct address is 0..7 (a byte has 8 bits); %IX0.8 is written %IX1.0");
  static_assert(E != address_error::hierarchical,
                "iecoop: hierarchical addresses (%IW2.5.7.1) depend on a fieldbus configuration iecoop does not have; "
                "write a flat address such as \"%IW2\"");
  static_assert(E != address_error::trailing_characters,
                "iecoop: unexpected characters after the direct address; write e.g. \"%IX0.5\" or \"%QW2\"");
}

// The address is parsed from a copy of its characters made inside the constant evaluation
// (as <iecoop/types/literals.hpp> does, for GCC's undefined-behaviour sanitizer).
template <fixed_string A>
struct address_chars {
  char chars[A.size + 1]{};
  constexpr address_chars() noexcept {
    for (std::size_t i = 0; i <= A.size; ++i) chars[i] = A.chars[i];
  }
  [[nodiscard]] constexpr std::string_view view() const noexcept { return {chars, A.size}; }
};

template <fixed_string A>
consteval address_parse parse_fixed_address() noexcept {
  const address_chars<A> copy;
  return parse_address(copy.view());
}

template <fixed_string A>
consteval io_address checked_address() noexcept {
  constexpr address_parse result = parse_fixed_address<A>();
  check_address<result.error()>();
  return result.value_or(io_address{});
}

}  // namespace detail

/// The direct address A, parsed while compiling: address_of<"%IX0.5">. A malformed address
/// does not compile.
template <detail::fixed_string A>
inline constexpr io_address address_of = detail::checked_address<A>();

}  // namespace iecoop

#include <iecoop/detail/pop_macros.hpp>
