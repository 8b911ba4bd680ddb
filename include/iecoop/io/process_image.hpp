// SPDX-License-Identifier: MIT
// iecoop/io/process_image.hpp — the process image: the memory of %I, %Q and %M, one static
// block of bytes per image type, as a PLC has one process image. Values are stored
// little-endian, as CODESYS stores them on x86 and Cortex-M; bit b of byte n is
// `(byte n >> b) & 1` (<iecoop/io/image_codec.hpp>). The I/O driver (<iecoop/io/driver.hpp>)
// fills the inputs at the start of each task cycle and takes the outputs at its end; located
// variables (<iecoop/io/located.hpp>) read and write their bytes.
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <span>
#include <type_traits>

#include <iecoop/config.hpp>
#include <iecoop/detail/diagnostics.hpp>
#include <iecoop/detail/fixed_string.hpp>
#include <iecoop/io/access_checks.hpp>
#include <iecoop/io/address.hpp>
#include <iecoop/io/image_codec.hpp>
#include <iecoop/types/elementary.hpp>
#include <iecoop/types/time.hpp>

#include <iecoop/detail/push_macros.hpp>
namespace iecoop {

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

}  // namespace iecoop

#include <iecoop/detail/pop_macros.hpp>
