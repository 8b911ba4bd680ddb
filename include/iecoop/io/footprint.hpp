// SPDX-License-Identifier: MIT
// iecoop/io/footprint.hpp — what an I/O driver touches in the process image: its footprint.
//
// A driver's input footprint is the %I bits its read_inputs() writes; its output footprint the
// %Q bits its write_outputs() sends on. Both are optional members of an IoDriver
// (<iecoop/io/driver.hpp>), runs of bits of one area (image_window):
//
//     struct local_card {                            // the station's terminals: %IB0..%IB3, %QB0
//       static constexpr std::array<image_window, 1> input_footprint() { return {window_of<"%IB0", 4>}; }
//       static constexpr std::array<image_window, 1> output_footprint() { return {window_of<"%QB0">}; }
//       void read_inputs(std::span<std::byte> in);
//       void write_outputs(std::span<const std::byte> out);
//     };
//
// io_chain refuses two drivers that write the same input bits: while compiling where both
// footprints are `static constexpr` (or one driver declares none), otherwise at the
// application's start(). A driver that declares no input footprint may write any input bit
// (`any_input`): alone it is fine, in a chain beside another driver that writes inputs it is not.
#pragma once

#include <array>
#include <concepts>
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <span>
#include <string_view>
#include <tuple>
#include <type_traits>

#include <iecoop/config.hpp>
#include <iecoop/detail/diagnostics.hpp>
#include <iecoop/detail/fixed_string.hpp>
#include <iecoop/detail/meta.hpp>
#include <iecoop/io/address.hpp>
#include <iecoop/io/process_image.hpp>
#include <iecoop/types/detail/type_hash.hpp>

#include <iecoop/detail/push_macros.hpp>

namespace iecoop {

/// A run of bits of one area of the process image: what a driver writes (%I) or reads (%Q), a
/// fieldbus device's mapping ("16 holding registers at %IW0", "8 coils at %IX4.0").
struct image_window {
  io_area area = io_area::input;
  std::uint32_t first_bit = 0;  ///< from bit 0 of byte 0 of the area
  std::uint32_t bits = 0;       ///< 16 per register

  [[nodiscard]] constexpr std::uint32_t first_byte() const noexcept { return first_bit / 8; }
  /// One past the last byte the window touches.
  [[nodiscard]] constexpr std::uint32_t end_byte() const noexcept {
    return static_cast<std::uint32_t>((std::uint64_t{first_bit} + bits + 7) / 8);
  }
  [[nodiscard]] constexpr std::uint32_t registers() const noexcept { return bits / 16; }
  [[nodiscard]] constexpr bool empty() const noexcept { return bits == 0; }
  /// TRUE if the two windows share a bit.
  [[nodiscard]] constexpr bool overlaps(const image_window& other) const noexcept {
    return area == other.area && !empty() && !other.empty() &&
           first_bit < std::uint64_t{other.first_bit} + other.bits && other.first_bit < std::uint64_t{first_bit} + bits;
  }

  friend constexpr bool operator==(const image_window&, const image_window&) noexcept = default;
};

/// The input footprint of a driver that may write any input bit: what a driver that declares
/// none is taken to declare (and callback_io without a footprint given).
inline constexpr image_window any_input{io_area::input, 0, 0xFFFF'FFFFU};

namespace detail {

template <fixed_string First, std::uint32_t Count, class Image>
consteval image_window checked_window() noexcept {
  static_assert(is_process_image<Image>::value, "iecoop: window_of<First, Count, Image> lies in a process_image<...>");
  constexpr io_address a = address_of<First>;
  static_assert(Count > 0,
                "iecoop: a window holds at least one bit, byte or word; give its count, window_of<\"%IB0\", 4>");
  constexpr std::uint64_t first = a.first_bit(Image::mode);
  constexpr std::uint64_t end = first + std::uint64_t{Count} * a.bit_count();
  static_assert(end <= std::uint64_t{Image::size_of(a.area)} * 8u,
                "iecoop: the window does not fit in the process image's area; make it smaller, or give the image more "
                "bytes (window_of<First, Count, Image>)");
  return {a.area, static_cast<std::uint32_t>(first), static_cast<std::uint32_t>(end - first)};
}

}  // namespace detail

/// `Count` values of the width of the address `First`, in the image `Image` (whose addressing
/// says where a word lies): window_of<"%IB0", 4> is %IB0..%IB3, window_of<"%IX0.0", 3> is
/// %IX0.0..%IX0.2, window_of<"%IW8", 8> is %IW8..%IW15. Checked while compiling, as located
/// variables are.
template <detail::fixed_string First, std::uint32_t Count = 1, class Image = default_process_image>
inline constexpr image_window window_of = detail::checked_window<First, Count, Image>();

/// Copies the window's bits from `from` to `to` (two copies of the same area), leaving every
/// other bit of `to` as it is.
inline void copy_window(std::span<std::byte> to, std::span<const std::byte> from, const image_window& w) noexcept {
  if (w.empty()) return;
  std::uint32_t byte = w.first_byte();
  const std::uint32_t end = w.end_byte();
  const std::uint32_t head = w.first_bit % 8;
  const std::uint32_t tail = (w.first_bit + w.bits) % 8;
  if (head == 0 && tail == 0) {  // whole bytes: registers, or bits from bit 0 in multiples of 8
    std::memcpy(to.data() + byte, from.data() + byte, end - byte);
    return;
  }
  for (; byte < end; ++byte) {
    unsigned mask = 0xFFU;
    if (byte == w.first_byte()) mask &= 0xFFU << head;
    if (byte + 1 == end && tail != 0) mask &= 0xFFU >> (8 - tail);
    const auto m = static_cast<std::byte>(mask);
    to[byte] = (to[byte] & ~m) | (from[byte] & m);
  }
}

namespace detail {

// --- A driver's declared footprint ------------------------------------------------------

/// D declares its input footprint while compiling: `static constexpr std::array<image_window, N>
/// input_footprint()`.
template <class D>
concept static_input_footprint =
    requires { typename std::integral_constant<std::size_t, D::input_footprint().size()>; } &&
    is_std_array<std::remove_cv_t<decltype(D::input_footprint())>>::value &&
    std::is_same_v<typename std::remove_cv_t<decltype(D::input_footprint())>::value_type, image_window>;

/// D has an input_footprint() of any kind.
template <class D>
concept names_input_footprint = requires(const D& d) { d.input_footprint(); };

/// D declares its input footprint at run time: `std::span<const image_window> input_footprint() const`.
template <class D>
concept runtime_input_footprint = !static_input_footprint<D> && requires(const D& d) {
  { d.input_footprint() } -> std::same_as<std::span<const image_window>>;
};

template <class D>
constexpr void check_footprint_form() noexcept {
  static_assert(!names_input_footprint<D> || static_input_footprint<D> || runtime_input_footprint<D>,
                "iecoop: a driver's input_footprint() is `static constexpr std::array<image_window, N> "
                "input_footprint()` (known while compiling) or `std::span<const image_window> input_footprint() "
                "const` (known at run time); give it one of these forms");
}

/// The static footprint, as a constant with static storage (a span of it outlives every call).
template <class D>
inline constexpr auto static_input_footprint_v = D::input_footprint();

inline constexpr std::array<image_window, 1> any_input_footprint{any_input};

/// The input footprint of `driver`: what it declares, or any_input if it declares nothing.
template <class D>
[[nodiscard]] constexpr std::span<const image_window> input_footprint_of(const D& driver) noexcept {
  if constexpr (static_input_footprint<D>) {
    return static_input_footprint_v<D>;
  } else if constexpr (runtime_input_footprint<D>) {
    return driver.input_footprint();
  } else {
    return any_input_footprint;
  }
}

/// The footprint of D as far as it is known while compiling: declared static, or none declared
/// (any_input). A footprint known only at run time is not.
template <class D>
inline constexpr bool footprint_known_while_compiling = static_input_footprint<D> || !names_input_footprint<D>;

template <class D>
constexpr std::span<const image_window> compile_time_footprint() noexcept {
  if constexpr (static_input_footprint<D>) {
    return static_input_footprint_v<D>;
  } else {
    return any_input_footprint;
  }
}

/// The name of a driver in a message: its type's, without namespaces and template arguments
/// (`modbus_server`, `local_card`).
template <class D>
constexpr std::string_view driver_name() noexcept {
  const std::string_view name = short_type_name<D>();
  return name.substr(0, name.find('<'));
}

// --- Two drivers writing the same input bits --------------------------------------------

/// The bits two windows share (an empty window if none).
[[nodiscard]] constexpr image_window shared_bits(const image_window& a, const image_window& b) noexcept {
  if (a.area != b.area || a.empty() || b.empty()) return {};
  const std::uint64_t first = a.first_bit > b.first_bit ? a.first_bit : b.first_bit;
  const std::uint64_t a_end = std::uint64_t{a.first_bit} + a.bits;
  const std::uint64_t b_end = std::uint64_t{b.first_bit} + b.bits;
  const std::uint64_t end = a_end < b_end ? a_end : b_end;
  if (first >= end) return {};
  return {a.area, static_cast<std::uint32_t>(first), static_cast<std::uint32_t>(end - first)};
}

/// The first input bits two footprints share (empty if none).
[[nodiscard]] constexpr image_window shared_inputs(std::span<const image_window> a,
                                                   std::span<const image_window> b) noexcept {
  for (const image_window& x : a) {
    if (x.area != io_area::input) continue;
    for (const image_window& y : b) {
      const image_window shared = shared_bits(x, y);
      if (!shared.empty()) return shared;
    }
  }
  return {};
}

/// Two drivers of a chain (indices from 0) and the input bits they both write.
struct footprint_clash {
  std::size_t first = 0;
  std::size_t second = 0;
  image_window shared{};
  bool first_unknown = false;   ///< the first declares no input footprint
  bool second_unknown = false;  ///< the second declares none

  [[nodiscard]] constexpr bool found() const noexcept { return !shared.empty(); }
};

[[nodiscard]] constexpr bool is_any_input(std::span<const image_window> footprint) noexcept {
  for (const image_window& w : footprint) {
    if (w == any_input) return true;
  }
  return false;
}

/// The first two of `footprints` (in chain order) that write a same input bit, or none.
/// `checked(i, j)`: whether the pair is to be looked at.
template <std::size_t N, class Checked>
[[nodiscard]] constexpr footprint_clash first_clash(const std::array<std::span<const image_window>, N>& footprints,
                                                    Checked checked) noexcept {
  for (std::size_t i = 0; i < N; ++i) {
    for (std::size_t j = i + 1; j < N; ++j) {
      if (!checked(i, j)) continue;
      const image_window shared = shared_inputs(footprints[i], footprints[j]);
      if (!shared.empty()) {
        return {i, j, shared, is_any_input(footprints[i]), is_any_input(footprints[j])};
      }
    }
  }
  return {};
}

/// A message built in a fixed buffer, at compile time or at run time ("iecoop: ..."); text that
/// does not fit is cut.
struct text_builder {
  char* out;
  std::size_t capacity;  // including the terminating '\0'
  std::size_t size = 0;

  constexpr text_builder& operator<<(std::string_view text) noexcept {
    for (const char c : text) {
      if (size + 1 < capacity) out[size++] = c;
    }
    if (capacity > 0) out[size] = '\0';
    return *this;
  }
  constexpr text_builder& operator<<(std::uint64_t n) noexcept {
    char digits[20]{};
    std::size_t count = 0;
    do {
      digits[count++] = static_cast<char>('0' + n % 10);
      n /= 10;
    } while (n != 0);
    char text[20]{};
    for (std::size_t i = 0; i < count; ++i) text[i] = digits[count - 1 - i];
    return *this << std::string_view(text, count);
  }
};

/// A window as the addresses it spans: %IB0..%IB3 for whole bytes, %IX0.4..%IX0.7 otherwise.
constexpr void write_window(text_builder& text, const image_window& w) noexcept {
  const std::string_view area = w.area == io_area::input ? "%I" : w.area == io_area::output ? "%Q" : "%M";
  const std::uint64_t last = std::uint64_t{w.first_bit} + w.bits - 1;
  if (w.first_bit % 8 == 0 && w.bits % 8 == 0) {
    text << area << "B" << std::uint64_t{w.first_bit / 8};
    if (w.bits > 8) text << ".." << area << "B" << last / 8;
    return;
  }
  text << area << "X" << std::uint64_t{w.first_bit / 8} << "." << std::uint64_t{w.first_bit % 8};
  if (w.bits > 1) text << ".." << area << "X" << last / 8 << "." << last % 8;
}

/// The message of a clash of drivers named `first` and `second`: "iecoop: io_chain: drivers 1
/// (local_card) and 2 (modbus_server) both write %IB0..%IB3; give each driver its own input area".
constexpr void write_clash(text_builder& text, const footprint_clash& c, std::string_view first,
                           std::string_view second) noexcept {
  text << "iecoop: io_chain: drivers " << std::uint64_t{c.first + 1} << " (" << first << ") and "
       << std::uint64_t{c.second + 1} << " (" << second << ")";
  if (c.first_unknown && c.second_unknown) {
    text << " may both write any input byte: neither declares its input footprint; declare what each writes "
            "(input_footprint(), docs/process-image.md), and give each driver its own input area";
    return;
  }
  text << " both write ";
  write_window(text, c.shared);
  if (c.first_unknown || c.second_unknown) {
    text << " (driver " << std::uint64_t{(c.first_unknown ? c.first : c.second) + 1}
         << " declares no input footprint: it may write any input byte); declare what it writes "
            "(input_footprint(), docs/process-image.md), and give each driver its own input area";
    return;
  }
  text << "; give each driver its own input area";
}

// --- The compile-time check of a chain --------------------------------------------------

template <class... D>
consteval footprint_clash static_clash() noexcept {
  constexpr std::size_t n = sizeof...(D);
  const std::array<std::span<const image_window>, n> footprints{compile_time_footprint<D>()...};
  constexpr std::array<bool, n> known{footprint_known_while_compiling<D>...};
  return first_clash(footprints, [&](std::size_t i, std::size_t j) { return known[i] && known[j]; });
}

template <class... D>
inline constexpr footprint_clash static_clash_v = static_clash<D...>();

/// The window's addresses as compile-time text.
template <image_window W>
consteval constant_text<48> window_text() noexcept {
  constant_text<48> result{};
  text_builder text{result.chars, sizeof result.chars};
  write_window(text, W);
  result.size = text.size;
  return result;
}

/// Instantiated for two drivers of an io_chain (numbered from 1) that write the same input
/// bits: the compiler prints them and the bits (`Shared`) in the template arguments.
template <std::size_t First, class FirstDriver, std::size_t Second, class SecondDriver, class Shared>
struct io_chain_inputs_overlap {
  static_assert(dependent_false<Shared>,
                "iecoop: io_chain: two drivers write the same input bits (the drivers, numbered from 1, and the "
                "bits, spelled in 'Shared', are in the template arguments above); give each driver its own input "
                "area");
  static constexpr bool value = false;
};

/// Instantiated for a driver of an io_chain that declares no input footprint (it may write any
/// input bit) beside another that writes inputs: the compiler prints both, numbered from 1.
template <std::size_t Undeclared, class UndeclaredDriver, std::size_t Other, class OtherDriver>
struct io_chain_footprint_undeclared {
  static_assert(dependent_false<UndeclaredDriver>,
                "iecoop: io_chain: the driver 'UndeclaredDriver' declares no input footprint, so it may write any "
                "input byte and shares no chain with 'OtherDriver', which writes inputs too (both numbered from 1 in "
                "the template arguments above); declare what it writes (input_footprint(), docs/process-image.md), "
                "and give each driver its own input area");
  static constexpr bool value = false;
};

template <std::size_t I, class... D>
using driver_at = std::tuple_element_t<I, std::tuple<D...>>;

/// No two drivers of the chain clash (footprint_report_t).
struct no_footprint_clash {};

/// The type whose instantiation reports the first clash of the chain's drivers whose footprints
/// are known while compiling (two that share an input bit, or one that declares none beside
/// another that writes inputs), no_footprint_clash if none: io_chain's constructor asks for its
/// size, so that the report is one step from the user's line.
template <class... D>
constexpr auto footprint_report() noexcept {
  constexpr footprint_clash c = static_clash_v<D...>;
  if constexpr (!c.found()) {
    return std::type_identity<no_footprint_clash>{};
  } else {
    using first = driver_at<c.first, D...>;
    using second = driver_at<c.second, D...>;
    if constexpr (c.first_unknown) {
      return std::type_identity<io_chain_footprint_undeclared<c.first + 1, first, c.second + 1, second>>{};
    } else if constexpr (c.second_unknown) {
      return std::type_identity<io_chain_footprint_undeclared<c.second + 1, second, c.first + 1, first>>{};
    } else {
      return std::type_identity<
          io_chain_inputs_overlap<c.first + 1, first, c.second + 1, second, spelled_t<window_text<c.shared>()>>>{};
    }
  }
}
template <class... D>
using footprint_report_t = typename decltype(footprint_report<D...>())::type;

// --- The optional configuration check of a driver ---------------------------------------

/// A driver's `configuration_error()`: nullptr, or why it must not run ("iecoop: ..."). The
/// application's start() refuses to start with a driver that reports one.
template <class D>
[[nodiscard]] const char* configuration_error_of(const D& driver) noexcept {
  if constexpr (requires {
                  { driver.configuration_error() } -> std::convertible_to<const char*>;
                }) {
    return driver.configuration_error();
  } else {
    return nullptr;
  }
}

}  // namespace detail

}  // namespace iecoop

#include <iecoop/detail/pop_macros.hpp>
