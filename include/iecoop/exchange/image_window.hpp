// SPDX-License-Identifier: MIT
// iecoop/exchange/image_window.hpp — a run of registers or bits of the process image, as a
// fieldbus device's I/O mapping gives it: "16 holding registers at %IW0", "8 coils at %IX4.0".
//
//     window_parse w = register_window("%IW0", 16, addressing::codesys, Image::input_bytes);
//     if (!w) puts(w.error);          // "iecoop: ..." — the address is no word, or lies outside the image
//     std::uint16_t r = load_register(Image::inputs(), *w, 3);     // %IW3, little-endian as stored
//     copy_window(Image::inputs(), snapshot, *w);                   // only the window's bits
//
// Registers are the image's 16-bit words as CODESYS stores them (little-endian: %IX0.0 is bit 0
// of the first register); bits count from the window's first bit. The windows are checked
// when made (a device's configuration is often read at run time), never when used. The window
// itself, image_window, and copy_window() are the I/O layer's (<iecoop/io/footprint.hpp>).
#pragma once

#include <cstddef>
#include <cstdint>
#include <span>
#include <string_view>

#include <iecoop/config.hpp>
#include <iecoop/io/address.hpp>
#include <iecoop/io/footprint.hpp>

#include <iecoop/detail/push_macros.hpp>

namespace iecoop {

/// A window, or why the configuration gives none (`error`: a message, "iecoop: ...; ...").
struct window_parse {
  image_window window{};
  const char* error = nullptr;

  [[nodiscard]] constexpr explicit operator bool() const noexcept { return error == nullptr; }
  [[nodiscard]] constexpr const image_window& operator*() const noexcept { return window; }
};

namespace detail {

constexpr window_parse window_error(const char* message) noexcept { return {{}, message}; }

constexpr const char* wrong_area_message(io_area wanted) noexcept {
  switch (wanted) {
    case io_area::input: return "iecoop: this mapping lies in the inputs; give an %I address (%IW0, %IX4.0)";
    case io_area::output: return "iecoop: this mapping lies in the outputs; give a %Q address (%QW0, %QX4.0)";
    default: return "iecoop: this mapping lies in the memory; give an %M address (%MW0, %MX4.0)";
  }
}

}  // namespace detail

/// `registers` 16-bit registers from the word address `first` (%IW0, %QW8) in area `area` of
/// an image with `area_bytes` bytes in that area.
[[nodiscard]] constexpr window_parse register_window(std::string_view first, std::uint32_t registers, io_area area,
                                                     addressing mode, std::size_t area_bytes) noexcept {
  const address_parse parsed = parse_address(first);
  if (!parsed) return detail::window_error("iecoop: a register mapping starts at a direct address; write it as %IW0");
  const io_address a = *parsed;
  if (a.area != area) return detail::window_error(detail::wrong_area_message(area));
  if (a.width != io_width::word) {
    return detail::window_error("iecoop: registers map to words; give a word address (%IW0, %QW4), not a bit or byte");
  }
  if (registers == 0) return detail::window_error("iecoop: a register mapping has at least one register; give a count");
  const std::uint64_t end = std::uint64_t{a.first_byte(mode)} + std::uint64_t{registers} * 2u;
  if (end > area_bytes) {
    return detail::window_error(
        "iecoop: the registers do not fit in the process image's area; map fewer, or give the image more bytes");
  }
  return {{area, a.first_byte(mode) * 8u, registers * 16u}, nullptr};
}

/// `bits` bits from the bit address `first` (%IX0.0, %QX4.3) in area `area`.
[[nodiscard]] constexpr window_parse bit_window(std::string_view first, std::uint32_t bits, io_area area,
                                                addressing mode, std::size_t area_bytes) noexcept {
  const address_parse parsed = parse_address(first);
  if (!parsed) return detail::window_error("iecoop: a bit mapping starts at a direct address; write it as %IX0.0");
  const io_address a = *parsed;
  if (a.area != area) return detail::window_error(detail::wrong_area_message(area));
  if (a.width != io_width::bit) {
    return detail::window_error("iecoop: coils and discrete inputs map to bits; give a bit address (%IX0.0, %QX2.4)");
  }
  if (bits == 0) return detail::window_error("iecoop: a bit mapping has at least one bit; give a count");
  const std::uint64_t end_bit = a.first_bit(mode) + bits;
  if (end_bit > std::uint64_t{area_bytes} * 8u) {
    return detail::window_error(
        "iecoop: the bits do not fit in the process image's area; map fewer, or give the image more bytes");
  }
  return {{area, static_cast<std::uint32_t>(a.first_bit(mode)), bits}, nullptr};
}

/// Bit `i` of the window in `area` (the bytes of the window's area).
[[nodiscard]] inline bool load_bit(std::span<const std::byte> area, const image_window& w, std::uint32_t i) noexcept {
  const std::uint32_t bit = w.first_bit + i;
  return ((std::to_integer<unsigned>(area[bit / 8]) >> (bit % 8)) & 1U) != 0;
}

inline void store_bit(std::span<std::byte> area, const image_window& w, std::uint32_t i, bool value) noexcept {
  const std::uint32_t bit = w.first_bit + i;
  const auto mask = static_cast<std::byte>(1U << (bit % 8));
  area[bit / 8] = value ? (area[bit / 8] | mask) : (area[bit / 8] & ~mask);
}

/// Register `i` of a register window: the image's word, little-endian.
[[nodiscard]] inline std::uint16_t load_register(std::span<const std::byte> area, const image_window& w,
                                                 std::uint32_t i) noexcept {
  const std::uint32_t byte = w.first_byte() + 2 * i;
  return static_cast<std::uint16_t>(std::to_integer<unsigned>(area[byte]) |
                                    (std::to_integer<unsigned>(area[byte + 1]) << 8));
}

inline void store_register(std::span<std::byte> area, const image_window& w, std::uint32_t i,
                           std::uint16_t value) noexcept {
  const std::uint32_t byte = w.first_byte() + 2 * i;
  area[byte] = static_cast<std::byte>(value & 0xFFU);
  area[byte + 1] = static_cast<std::byte>(value >> 8);
}

}  // namespace iecoop

#include <iecoop/detail/pop_macros.hpp>
