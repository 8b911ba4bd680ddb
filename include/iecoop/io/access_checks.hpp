// SPDX-License-Identifier: MIT
// iecoop/io/access_checks.hpp — the compile-time checks of a typed access to a
// direct address of a process image: the type fits the address's width, the bytes lie inside
// the area; each broken rule is its own static_assert, naming the numbers it compared.
// IWYU pragma: private, include <iecoop/io/process_image.hpp>
#pragma once

#include <cstddef>
#include <cstdint>
#include <type_traits>

#include <iecoop/config.hpp>
#include <iecoop/detail/diagnostics.hpp>
#include <iecoop/detail/fixed_string.hpp>
#include <iecoop/io/address.hpp>
#include <iecoop/io/image_codec.hpp>
#include <iecoop/types/elementary.hpp>

#include <iecoop/detail/push_macros.hpp>

namespace iecoop {

template <std::size_t InputBytes, std::size_t OutputBytes, std::size_t MemoryBytes, addressing Mode, class Tag>
struct process_image;

namespace detail {

template <class T>
struct is_process_image : std::false_type {};
template <std::size_t I, std::size_t O, std::size_t M, addressing Mode, class Tag>
struct is_process_image<process_image<I, O, M, Mode, Tag>> : std::true_type {};

/// The type that can be stored at an address: a BOOL, or an elementary type of the
/// address's size.
template <class T>
constexpr bool fits_width(io_width w) noexcept {
  if constexpr (std::is_same_v<T, BOOL>) {
    return w == io_width::bit || w == io_width::byte;  // CODESYS allocates a BOOL at %IB byte-wise
  } else if constexpr (io_repr<T>::stored) {
    return w != io_width::bit && sizeof(typename io_repr<T>::raw) == bytes_of(w);
  } else {
    return false;
  }
}

/// The type a value at an address of width W has by default: BOOL, BYTE, WORD, DWORD, LWORD.
template <io_width W>
struct default_type {
  using type = BOOL;
};
template <>
struct default_type<io_width::byte> {
  using type = BYTE;
};
template <>
struct default_type<io_width::word> {
  using type = WORD;
};
template <>
struct default_type<io_width::dword> {
  using type = DWORD;
};
template <>
struct default_type<io_width::lword> {
  using type = LWORD;
};
template <io_width W>
using default_type_t = typename default_type<W>::type;

/// The type of a value fits the width W of its address (Fits), one static_assert per width.
template <io_width W, bool Fits>
struct width_holds {
  static_assert(
      Fits || W != io_width::bit,
      "iecoop: a bit address (%IX, %QX, %MX) holds a BOOL; declare the variable BOOL, or give it the address of "
      "its size: %IB for BYTE/SINT/USINT, %IW for WORD/INT/UINT, %ID for DWORD/DINT/UDINT/REAL/TIME, %IL for 64 bits");
  static_assert(
      Fits || W != io_width::byte,
      "iecoop: a byte address (%IB, %QB, %MB) holds a BYTE, SINT, USINT or BOOL; give the variable the address of "
      "its size: %IW for WORD/INT/UINT, %ID for DWORD/DINT/UDINT/REAL/TIME, %IL for LWORD/LINT/ULINT/LREAL/LTIME");
  static_assert(
      Fits || W != io_width::word,
      "iecoop: a word address (%IW, %QW, %MW) holds a WORD, INT or UINT; give the variable the address of its "
      "size: %IX for BOOL, %IB for BYTE/SINT/USINT, %ID for DWORD/DINT/UDINT/REAL/TIME, %IL for 64 bits");
  static_assert(
      Fits || W != io_width::dword,
      "iecoop: a double-word address (%ID, %QD, %MD) holds a DWORD, DINT, UDINT, REAL or TIME; give the variable "
      "the address of its size: %IX for BOOL, %IB for 8 bits, %IW for 16 bits, %IL for LWORD/LINT/ULINT/LREAL/LTIME");
  static_assert(
      Fits || W != io_width::lword,
      "iecoop: a long-word address (%IL, %QL, %ML) holds an LWORD, LINT, ULINT, LREAL or LTIME; give the variable "
      "the address of its size: %IX for BOOL, %IB for 8 bits, %IW for 16 bits, %ID for 32 bits");
};

/// T is an IEC elementary type that can be stored at an address.
template <bool Elementary>
struct elementary_holds {
  static_assert(
      Elementary,
      "iecoop: a value at a direct address has an elementary IEC type (BOOL, BYTE..LWORD, SINT..ULINT, REAL, "
      "LREAL, TIME, LTIME); declare the located variable with one of them, e.g. located<INT, \"%IW2\">, or pass "
      "an IEC value, e.g. INT(300)");
};

/// The checks of the type of a value at address A.
template <class T, io_address A>
struct address_holds
    : elementary_holds<std::is_same_v<T, BOOL> || io_repr<T>::stored>,
      width_holds<A.width, !(std::is_same_v<T, BOOL> || io_repr<T>::stored) || fits_width<T>(A.width)> {
  static constexpr bool value = fits_width<T>(A.width);
};

/// The address's bytes, [FirstByte, FirstByte + ByteCount), lie inside an area of AreaBytes
/// bytes. The template arguments, which the compiler prints, are the numbers to compare.
template <std::uint32_t FirstByte, std::uint32_t ByteCount, std::size_t AreaBytes>
struct address_within_area {
  static_assert(std::size_t{FirstByte} + ByteCount <= AreaBytes,
                "iecoop: the address lies outside its area of the process image (the template arguments are its first "
                "byte, its size and the size of the area); use an address inside the area, or a process_image<> with a "
                "larger area (CODESYS: %IW5 is bytes 10..11)");
  static constexpr bool value = std::size_t{FirstByte} + ByteCount <= AreaBytes;
};

/// Every check of a typed access to address A of Image; `value` is TRUE once they hold.
/// (An address that does not parse has reported its own error: nothing more is checked.)
template <class T, io_address A, class Image, bool Parsed>
struct access_check {
  static constexpr bool value = false;
};
template <class T, io_address A, class Image>
  requires is_process_image<Image>::value
struct access_check<T, A, Image, true>
    : address_holds<T, A>, address_within_area<A.first_byte(Image::mode), A.byte_count(), Image::size_of(A.area)> {
  static constexpr bool value =
      address_holds<T, A>::value &&
      address_within_area<A.first_byte(Image::mode), A.byte_count(), Image::size_of(A.area)>::value;
};
template <class T, io_address A, class Image>
  requires(!is_process_image<Image>::value)
struct access_check<T, A, Image, true> {
  static_assert(
      dependent_false<T, Image>,
      "iecoop: the image of a located variable is a process_image<...>; e.g. located<BOOL, \"%IX0.0\", my_image>");
  static constexpr bool value = false;
};

/// TRUE if the text A is a valid direct address.
template <fixed_string A>
inline constexpr bool address_parses = parse_fixed_address<A>().has_value();

/// The checks of a typed access to address A of Image. Instantiate it for its static_asserts
/// (`static_assert(sizeof(access_check_t<...>) > 0)`), and test access_valid<> for the
/// result: Clang treats the members of a class whose static_assert failed as non-constant.
template <class T, fixed_string A, class Image>
using access_check_t = access_check<T, address_of<A>, Image, address_parses<A>>;

template <class T, io_address A, class Image, bool Parsed>
constexpr bool access_ok() noexcept {
  if constexpr (!Parsed || !is_process_image<Image>::value) {
    return false;
  } else {
    return fits_width<T>(A.width) && std::size_t{A.first_byte(Image::mode)} + A.byte_count() <= Image::size_of(A.area);
  }
}

/// TRUE if T may be read and written at address A of Image.
template <class T, fixed_string A, class Image>
inline constexpr bool access_valid = access_ok<T, address_of<A>, Image, address_parses<A>>();

}  // namespace detail

}  // namespace iecoop

#include <iecoop/detail/pop_macros.hpp>
