// SPDX-License-Identifier: MIT
// iecoop/io/process_image.hpp — the process image (the memory of %I, %Q and %M) and located
// variables, ST's `AT %IX0.5`.
//
//     // VAR_GLOBAL  bStart AT %IX0.5 : BOOL;  bMotor AT %QX0.0 : BOOL;  iSpeed AT %IW2 : INT;  END_VAR
//     struct GVL_IO {
//       [[no_unique_address]] located<BOOL, "%IX0.5"> bStart;
//       [[no_unique_address]] located<BOOL, "%QX0.0"> bMotor;
//       [[no_unique_address]] located<INT, "%IW2"> iSpeed;
//       using LOCATED = pins<&GVL_IO::bStart, &GVL_IO::bMotor, &GVL_IO::iSpeed>;
//     };
//     ...
//     io.bMotor = io.bStart & (io.iSpeed > 100);
//
// A process image is a type with static storage, as a PLC has one process image: a
// located variable is an empty object that reads and writes its bytes, whose address is a
// link-time constant. Values are stored little-endian, as CODESYS stores them on x86 and
// Cortex-M; bit b of byte n is `(byte n >> b) & 1`. The I/O driver (<iecoop/io/driver.hpp>) fills
// the inputs at the start of each task cycle and takes the outputs at its end.
#pragma once

#include <array>
#include <bit>
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <span>
#include <string_view>
#include <type_traits>
#include <utility>

#include <iecoop/config.hpp>
#include <iecoop/detail/diagnostics.hpp>
#include <iecoop/detail/fixed_string.hpp>
#include <iecoop/detail/value_operators.hpp>
#include <iecoop/io/address.hpp>
#include <iecoop/pou/call_interface.hpp>
#include <iecoop/types/elementary.hpp>
#include <iecoop/types/time.hpp>

#include <iecoop/detail/push_macros.hpp>

namespace iecoop {

template <std::size_t InputBytes, std::size_t OutputBytes, std::size_t MemoryBytes, addressing Mode, class Tag>
struct process_image;

namespace detail {

template <class T>
struct is_process_image : std::false_type {};
template <std::size_t I, std::size_t O, std::size_t M, addressing Mode, class Tag>
struct is_process_image<process_image<I, O, M, Mode, Tag>> : std::true_type {};

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

/**
 * The process image: the bytes of the inputs (%I), outputs (%Q) and memory (%M).
 *
 * The storage is static, one image per type, as a PLC has one process image; the sizes
 * are the number of bytes of each area and `Mode` says how addresses map to bytes (see
 * <iecoop/io/address.hpp>). Give an image a distinct `Tag` to have a second one (in tests, a
 * simulation of two PLCs). All bytes start at 0.
 *
 *     using image = process_image<>;                       // 64 input, 64 output, 256 memory bytes
 *     image::write<INT, "%IW2">(INT(300));                 // what the I/O driver does
 *     INT speed = image::read<INT, "%IW2">();
 *     std::span<std::byte, 64> in = image::inputs();
 */
template <std::size_t InputBytes = 64, std::size_t OutputBytes = 64, std::size_t MemoryBytes = 256,
          addressing Mode = addressing::codesys, class Tag = void>
struct process_image {
  static constexpr std::size_t input_bytes = InputBytes;
  static constexpr std::size_t output_bytes = OutputBytes;
  static constexpr std::size_t memory_bytes = MemoryBytes;
  static constexpr addressing mode = Mode;
  using tag = Tag;

  /// The number of bytes of an area.
  static constexpr std::size_t size_of(io_area a) noexcept {
    switch (a) {
      case io_area::input: return InputBytes;
      case io_area::output: return OutputBytes;
      case io_area::memory: return MemoryBytes;
    }
    return 0;
  }

  /// The input bytes (%I): written by the I/O driver at the start of each task cycle.
  static std::span<std::byte, InputBytes> inputs() noexcept { return std::span<std::byte, InputBytes>(inputs_); }
  /// The output bytes (%Q): taken by the I/O driver at the end of each task cycle.
  static std::span<std::byte, OutputBytes> outputs() noexcept { return std::span<std::byte, OutputBytes>(outputs_); }
  /// The memory bytes (%M).
  static std::span<std::byte, MemoryBytes> memory() noexcept { return std::span<std::byte, MemoryBytes>(memory_); }
  /// The bytes of an area.
  static std::span<std::byte> area(io_area a) noexcept {
    switch (a) {
      case io_area::input: return inputs_;
      case io_area::output: return outputs_;
      case io_area::memory: return memory_;
    }
    return {};
  }

  /// Sets every byte of the three areas to 0, as at a cold start.
  static void clear() noexcept {
    inputs_.fill(std::byte{0});
    outputs_.fill(std::byte{0});
    memory_.fill(std::byte{0});
  }

  /// The T at address A, checked as a located variable is: read<INT, "%IW2">(). This is
  /// also how to see the same bytes at another width (read<BYTE, "%IB0">() beside the bits
  /// %IX0.0..%IX0.7).
  template <class T, detail::fixed_string A>
  static T read() noexcept {
    constexpr io_address address = address_of<A>;
    static_assert(sizeof(detail::access_check_t<T, A, process_image>) > 0);  // its static_asserts report misuse
    if constexpr (detail::access_valid<T, A, process_image>) {
      return detail::image_load<T, address, Mode>(area_data(address.area));
    } else {
      return T{};
    }
  }
  /// Writes the T at address A, in any area (this is how drivers and tests set inputs):
  /// write<BOOL, "%IX0.5">(TRUE).
  template <class T, detail::fixed_string A>
  static void write(T value) noexcept {
    constexpr io_address address = address_of<A>;
    static_assert(sizeof(detail::access_check_t<T, A, process_image>) > 0);  // its static_asserts report misuse
    if constexpr (detail::access_valid<T, A, process_image>) {
      detail::image_store<T, address, Mode>(area_data(address.area), value);
    }
  }

  /// The first byte of an area (for located variables).
  static std::byte* area_data(io_area a) noexcept {
    switch (a) {
      case io_area::input: return inputs_.data();
      case io_area::output: return outputs_.data();
      case io_area::memory: return memory_.data();
    }
    return nullptr;
  }

 private:
  alignas(8) static inline std::array<std::byte, InputBytes> inputs_{};
  alignas(8) static inline std::array<std::byte, OutputBytes> outputs_{};
  alignas(8) static inline std::array<std::byte, MemoryBytes> memory_{};
};

/// The process image located variables use unless told otherwise: 64 input bytes, 64
/// output bytes, 256 memory bytes, CODESYS addressing.
using default_process_image = process_image<>;

/**
 * A located variable, ST's `AT %IX0.5`: `bStart AT %IX0.5 : BOOL;` is
 * `located<BOOL, "%IX0.5"> bStart;`.
 *
 * It is an empty object: its value lives in the process image `Image`, at the address
 * given (checked at compile time: the type must fit the address's size and the address must
 * lie inside the image). Declare members `[[no_unique_address]]` so that they take no room
 * in their block, program or global variable list.
 *
 * In expressions it is its value (`bStart & !bStop`, `iSpeed + 1`, `if (bStart)`); %Q and
 * %M variables are assigned like variables (`bMotor = TRUE;`). A %I variable is read only:
 * the I/O driver writes it at the start of each task cycle.
 *
 * Sizes: %IX/%QX/%MX hold a BOOL; %IB a BYTE, SINT, USINT (or a BOOL, stored byte-wise as
 * CODESYS does); %IW a WORD, INT, UINT; %ID a DWORD, DINT, UDINT, REAL, TIME; %IL an LWORD,
 * LINT, ULINT, LREAL, LTIME.
 *
 * List located members in `using LOCATED = pins<&GVL::bStart, ...>;` so that
 * check_located<> rejects two of them that share a bit. Two located variables of the same
 * type are the same variable (the same bytes); copying a block copies no I/O.
 */
template <class T, detail::fixed_string Address, class Image = default_process_image>
class located : public detail::condition_conversion<located<T, Address, Image>, T>,
                public detail::widening_conversion<located<T, Address, Image>, T> {
 public:
  using value_type = T;
  using image_type = Image;
  using iecoop_value_wrapper = void;  // in expressions, its value (detail/value_operators.hpp)

  /// The variable's direct address.
  static constexpr io_address address = address_of<Address>;

 private:
  using check = detail::access_check_t<T, Address, Image>;
  static_assert(sizeof(check) > 0);  // instantiates the checks, whose own static_asserts say what is wrong
  static constexpr bool checked = detail::access_valid<T, Address, Image>;

 public:
  constexpr located() noexcept = default;
  constexpr located(const located&) noexcept = default;
  /// Copying a located variable to one of the same type (that is, at the same address) has
  /// nothing to do; a located variable at another address converts to its value first.
  constexpr located& operator=(const located&) noexcept = default;

  /// The value, read from the process image.
  [[nodiscard]] T get() const noexcept {
    if constexpr (checked) {
      return detail::image_load<T, address, Image::mode>(Image::area_data(address.area));
    } else {
      return T{};
    }
  }
  operator T() const noexcept { return get(); }  // implicit: reads as the variable

  /// Writes the value to the process image (%Q and %M only). A non-template operand, so that
  /// constants convert as in any assignment (`iCount = 5;`).
  located& operator=(const T& value) noexcept {
    static_assert(
        address.area != io_area::input,
        "iecoop: a %I... located variable is an input, written by the I/O driver at the start of each task "
        "cycle; the program only reads it. Give the variable a %Q (output) or %M (memory) address, or set the "
        "field value through simulated_io::set<\"%I...\">() or Image::write<T, \"%I...\">()");
    if constexpr (checked && address.area != io_area::input) {
      detail::image_store<T, address, Image::mode>(Image::area_data(address.area), value);
    }
    return *this;
  }

  /// From another variable wrapper whose value converts implicitly. Compound assignments
  /// (`iCount += 1;`) are those of every variable wrapper (detail/value_operators.hpp).
  template <class V>
    requires detail::converts_through_wrapper<T, V>
  located& operator=(const V& other) noexcept {
    const T value = detail::value_of(other);
    return *this = value;
  }
  /// A value of a type that ST converts only explicitly: rejected, naming the conversion.
  template <class V>
    requires detail::rejected_value<T, V>
  constexpr void operator=(const V&) {
    detail::reject_value<T, V>();
  }
};

/**
 * A directly represented variable used as it stands in ST: `%IX5` in an expression is
 * `at<"%IX5">`, `%QX1.0 := TRUE;` is `at<"%QX1.0"> = TRUE;`. Its type follows the size:
 * BOOL (X), BYTE, WORD, DWORD, LWORD; use located<T, "..."> for another type.
 *
 *     CMD_TMR("IN"_ = at<"%IX5">, "PT"_ = 300);   // ST: CMD_TMR(IN := %IX5, PT := 300);
 */
template <detail::fixed_string Address, class Image = default_process_image>
inline located<detail::default_type_t<address_of<Address>.width>, Address, Image> at{};

// ---------------------------------------------------------------------------------------
// The overlap check of a set of located variables

namespace detail {

template <class T>
struct is_located : std::false_type {};
template <class T, fixed_string A, class Image>
struct is_located<located<T, A, Image>> : std::true_type {};

template <class M>
struct member_pointer_parts;
template <class C, class V>
struct member_pointer_parts<V C::*> {
  using owner = C;
  using type = std::remove_cv_t<V>;
};

/// The located<> type a LOCATED entry designates.
template <auto Member>
using located_type_of = typename member_pointer_parts<decltype(Member)>::type;

/// A block's or list's `using LOCATED = pins<...>;`, as pou/call_interface.hpp reads VAR_INPUT: along the
/// EXTENDS chain, the base's first, so a derived block's own list does not hide its base's.
struct located_section {
  template <class B>
  using declared = typename B::LOCATED;
  static constexpr std::string_view keyword = "LOCATED";
};

template <class... Lists>
struct concat_all {
  using type = pins<>;
};
template <class First, class... Rest>
struct concat_all<First, Rest...> {
  using type = typename concat_pins<First, typename concat_all<Rest...>::type>::type;
};

/// Where one located variable lies: its image (as the index of the first entry with the same
/// image), its identity (the index of the first entry naming the same member) and its bits.
struct located_extent {
  std::size_t image;
  std::size_t identity;
  io_area area;
  std::uint64_t first_bit;
  std::uint64_t bit_count;
};

template <auto A, auto B>
constexpr bool same_member() noexcept {
  if constexpr (std::is_same_v<decltype(A), decltype(B)>) {
    return A == B;
  } else {
    return false;
  }
}

template <auto Member, auto... All>
constexpr located_extent extent_of() noexcept {
  using L = located_type_of<Member>;
  using image = typename L::image_type;
  constexpr bool same_image[] = {std::is_same_v<image, typename located_type_of<All>::image_type>...};
  constexpr bool same[] = {same_member<Member, All>()...};
  located_extent e{};
  e.image = 0;
  while (!same_image[e.image]) ++e.image;
  e.identity = 0;
  while (!same[e.identity]) ++e.identity;
  e.area = L::address.area;
  e.first_bit = L::address.first_bit(image::mode);
  e.bit_count = L::address.bit_count();
  return e;
}

struct overlap_pair {
  std::size_t first;
  std::size_t second;
};

/// The first two entries of the list that share a bit, or {size, size}.
template <auto... Members>
constexpr overlap_pair first_overlap(pins<Members...>) noexcept {
  constexpr std::size_t n = sizeof...(Members);
  if constexpr (n < 2) {
    return {n, n};
  } else {
    constexpr located_extent extents[] = {extent_of<Members, Members...>()...};
    for (std::size_t i = 0; i < n; ++i) {
      for (std::size_t j = i + 1; j < n; ++j) {
        const located_extent& a = extents[i];
        const located_extent& b = extents[j];
        if (a.identity == b.identity || a.image != b.image || a.area != b.area) continue;
        if (a.first_bit < b.first_bit + b.bit_count && b.first_bit < a.first_bit + a.bit_count) return {i, j};
      }
    }
    return {n, n};
  }
}

/// Every entry of a LOCATED list is a located<> member.
template <auto... Members>
constexpr bool all_located(pins<Members...>) noexcept {
  return (is_located<located_type_of<Members>>::value && ...);
}

/// Instantiated for two listed located variables that overlap: the compiler prints the two
/// members (the template arguments) with the message.
template <auto First, auto Second, bool Disjoint = false>
struct located_overlap {
  static_assert(
      Disjoint,
      "iecoop: two located variables overlap (their names are in the template arguments above); give each its "
      "own address, or read the other width through the process image (Image::read<...>)");
  static constexpr bool value = false;
};

template <class... Objects>
using all_located_t = typename concat_all<typename section_pins<located_section, Objects>::type...>::type;

}  // namespace detail

namespace detail {
template <class... Objects>
constexpr bool located_disjoint_impl() noexcept {
  using list = all_located_t<Objects...>;
  static_assert(
      all_located(list{}),
      "iecoop: LOCATED lists located<> members only, e.g. using LOCATED = pins<&GVL_IO::bStart, &GVL_IO::bMotor>;");
  if constexpr (all_located(list{})) {
    return first_overlap(list{}).first == list::size;
  } else {
    return false;
  }
}
}  // namespace detail

/// TRUE if no two located variables listed in the LOCATED lists of Objects share a bit
/// (types without LOCATED list none). Does not stop compilation; check_located<> does.
template <class... Objects>
inline constexpr bool located_disjoint = detail::located_disjoint_impl<Objects...>();

/**
 * Rejects, at compile time, two located variables that share a bit: gathers the LOCATED
 * lists of all Objects (a block, program or global variable list lists its located
 * members, `using LOCATED = pins<&GVL_IO::bStart, ...>;`) and fails to compile, naming the
 * two members, if two of the same image and area overlap. Two BOOLs in the same byte do not
 * overlap. The scheduler calls it for the programs it runs; call it yourself for others:
 *
 *     iecoop::check_located<GVL_IO, PLC_PRG>();
 *
 * Deliberate aliasing (an input read as bits and as a byte) reads through the image,
 * `Image::read<BYTE, "%IB0">()`, or uses a located variable that is not listed.
 */
template <class... Objects>
constexpr void check_located() noexcept {
  using list = detail::all_located_t<Objects...>;
  static_assert(
      detail::all_located(list{}),
      "iecoop: LOCATED lists located<> members only, e.g. using LOCATED = pins<&GVL_IO::bStart, &GVL_IO::bMotor>;");
  if constexpr (detail::all_located(list{})) {
    constexpr detail::overlap_pair hit = detail::first_overlap(list{});
    if constexpr (hit.first < list::size) {
      static_assert(sizeof(detail::located_overlap<pin<list, hit.first>, pin<list, hit.second>>) > 0);  // reports
    }
  }
}

}  // namespace iecoop

#include <iecoop/detail/pop_macros.hpp>
