// SPDX-License-Identifier: MIT
// iecoop/io/image_codec.hpp — how a value is stored in the process image: the
// unsigned integer of its size, little-endian (as CODESYS stores it on x86 and Cortex-M), a
// BOOL as one bit; image_load and image_store read and write a value at a checked address.
// IWYU pragma: private, include <iecoop/io/process_image.hpp>
#pragma once

#include <bit>
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <type_traits>

#include <iecoop/config.hpp>
#include <iecoop/io/address.hpp>
#include <iecoop/types/elementary.hpp>
#include <iecoop/types/time.hpp>

#include <iecoop/detail/push_macros.hpp>

namespace iecoop {

namespace detail {

template <std::size_t Bytes>
struct unsigned_of;
template <>
struct unsigned_of<1> {
  using type = std::uint8_t;
};
template <>
struct unsigned_of<2> {
  using type = std::uint16_t;
};
template <>
struct unsigned_of<4> {
  using type = std::uint32_t;
};
template <>
struct unsigned_of<8> {
  using type = std::uint64_t;
};

/// How a value of type T is stored in the image: as the unsigned integer `raw` of its size.
/// Only the IEC elementary types of 1, 2, 4 and 8 bytes (not BOOL, which is stored as a bit
/// or a byte) have one.
template <class T>
struct io_repr {
  static constexpr bool stored = false;
};
template <class Rep, integer_kind Kind>
struct io_repr<integer<Rep, Kind>> {
  static constexpr bool stored = true;
  using raw = typename unsigned_of<sizeof(Rep)>::type;
  static constexpr raw to_raw(integer<Rep, Kind> v) noexcept { return static_cast<raw>(v.value()); }
  static constexpr integer<Rep, Kind> from_raw(raw r) noexcept { return integer<Rep, Kind>(static_cast<Rep>(r)); }
};
template <class Rep>
struct io_repr<real<Rep>> {
  static constexpr bool stored = true;
  using raw = typename unsigned_of<sizeof(Rep)>::type;
  static constexpr raw to_raw(real<Rep> v) noexcept { return std::bit_cast<raw>(v.value()); }
  static constexpr real<Rep> from_raw(raw r) noexcept { return real<Rep>(std::bit_cast<Rep>(r)); }
};
template <class Rep, class Period>
struct io_repr<basic_time<Rep, Period>> {
  static constexpr bool stored = true;
  using raw = typename unsigned_of<sizeof(Rep)>::type;
  static constexpr raw to_raw(basic_time<Rep, Period> v) noexcept { return static_cast<raw>(v.count()); }
  static constexpr basic_time<Rep, Period> from_raw(raw r) noexcept {
    return basic_time<Rep, Period>::from_ticks(static_cast<Rep>(r));
  }
};

/// The unsigned integer v with its bytes in the opposite order.
template <class U>
constexpr U byte_swap(U v) noexcept {
  std::uint64_t in = v;
  std::uint64_t swapped = 0;
  for (std::size_t i = 0; i < sizeof(U); ++i) {
    swapped = (swapped << 8) | (in & 0xFFu);
    in >>= 8;
  }
  return static_cast<U>(swapped);
}

/// The value of an unsigned integer read from / written to little-endian bytes.
template <class U>
constexpr U little_endian(U v) noexcept {
  if constexpr (std::endian::native == std::endian::big) {
    return byte_swap(v);
  } else {
    return v;
  }
}

/// Reads the T at address A (checked) from the bytes of its area.
template <class T, io_address A, addressing Mode>
inline T image_load(const std::byte* area) noexcept {
  constexpr std::uint32_t first = A.first_byte(Mode);
  if constexpr (std::is_same_v<T, BOOL>) {
    const unsigned byte = std::to_integer<unsigned>(area[first]);
    if constexpr (A.width == io_width::bit) {
      return BOOL(((byte >> A.bit) & 1u) != 0u);
    } else {
      return BOOL(byte != 0u);
    }
  } else {
    using raw = typename io_repr<T>::raw;
    raw r;
    std::memcpy(&r, area + first, sizeof r);
    return io_repr<T>::from_raw(little_endian(r));
  }
}

/// Writes the T at address A (checked) to the bytes of its area.
template <class T, io_address A, addressing Mode>
inline void image_store(std::byte* area, const T& value) noexcept {
  constexpr std::uint32_t first = A.first_byte(Mode);
  if constexpr (std::is_same_v<T, BOOL>) {
    if constexpr (A.width == io_width::bit) {
      constexpr std::byte mask{static_cast<unsigned char>(1u << A.bit)};
      area[first] = static_cast<bool>(value) ? (area[first] | mask) : (area[first] & ~mask);
    } else {
      area[first] =
          std::byte{static_cast<bool>(value) ? std::uint8_t{1} : std::uint8_t{0}};  // CODESYS stores TRUE as 1
    }
  } else {
    const auto r = little_endian(io_repr<T>::to_raw(value));
    std::memcpy(area + first, &r, sizeof r);
  }
}

}  // namespace detail

}  // namespace iecoop

#include <iecoop/detail/pop_macros.hpp>
