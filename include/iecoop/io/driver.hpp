// SPDX-License-Identifier: MIT
// iecoop/io/driver.hpp — the pluggable I/O: what connects the process image to the field.
//
// Each task cycle the scheduler calls the driver's read_inputs() with the input bytes of the
// process image before the programs run (the inputs are latched: they do not change during
// the cycle), and write_outputs() with the output bytes after they ran.
//
//   IoDriver        the concept: read_inputs(std::span<std::byte>), write_outputs(std::span<const std::byte>)
//   no_io           does nothing (the default)
//   simulated_io<>  a simulated field for tests: set inputs, read back outputs, count cycles
//   callback_io     two function pointers and a context pointer, for real hardware
//   io_chain        several drivers as one: a local I/O card, a fieldbus and a Modbus server, say;
//                   two of them that write the same input bits are refused
//
// A driver may declare what it touches (<iecoop/io/footprint.hpp>): input_footprint(), the %I
// bits it writes, and output_footprint(), the %Q bits it sends on; and configuration_error(),
// why it must not run (the application's start() refuses it then).
#pragma once

#include <array>
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
#include <iecoop/fault.hpp>
#include <iecoop/io/address.hpp>
#include <iecoop/io/footprint.hpp>
#include <iecoop/io/process_image.hpp>
#include <iecoop/types/detail/value_operators.hpp>
#include <iecoop/types/elementary.hpp>

#include <iecoop/detail/push_macros.hpp>

namespace iecoop {

/**
 * An I/O driver: `read_inputs(inputs)` fills the input bytes of the process image from the
 * field, `write_outputs(outputs)` sends the output bytes to it. The spans are the whole
 * areas; a driver that knows fewer bytes leaves the others alone.
 */
template <class D>
concept IoDriver = requires(D& driver, std::span<std::byte> inputs, std::span<const std::byte> outputs) {
  driver.read_inputs(inputs);
  driver.write_outputs(outputs);
};

/// The driver of a PLC without I/O: the inputs keep their values, the outputs go nowhere.
struct no_io {
  constexpr void read_inputs(std::span<std::byte>) noexcept {}
  constexpr void write_outputs(std::span<const std::byte>) noexcept {}
  /// It writes no input and sends no output.
  static constexpr std::array<image_window, 0> input_footprint() noexcept { return {}; }
  static constexpr std::array<image_window, 0> output_footprint() noexcept { return {}; }
};

/**
 * A driver for real hardware without heap or std::function: two function pointers and a
 * context pointer passed to both.
 *
 *     void read_gpio(std::span<std::byte> in, void* ctx)        { in[0] = std::byte(GPIOA->IDR & 0xFF); }
 *     void write_gpio(std::span<const std::byte> out, void* ctx) { GPIOB->ODR = std::to_integer<unsigned>(out[0]); }
 *     callback_io io{&read_gpio, &write_gpio};
 *
 * A null function does nothing (a device with inputs only, or outputs only).
 *
 * Its input footprint is what `inputs` says (the windows must outlive it); without them it may
 * write any input byte, which io_chain refuses beside another driver that writes inputs; with a
 * null read function it writes none:
 *
 *     static constexpr std::array card_inputs{window_of<"%IB0", 4>};   // %IB0..%IB3
 *     callback_io io{&read_gpio, &write_gpio, &board, card_inputs};
 */
class callback_io {
 public:
  using read_function = void (*)(std::span<std::byte> inputs, void* context);
  using write_function = void (*)(std::span<const std::byte> outputs, void* context);

  constexpr callback_io() noexcept = default;
  constexpr callback_io(read_function read, write_function write, void* context = nullptr,
                        std::span<const image_window> inputs = {}) noexcept
      : read_(read), write_(write), context_(context), inputs_(inputs) {}

  void read_inputs(std::span<std::byte> inputs) const {
    if (read_ != nullptr) read_(inputs, context_);
  }
  void write_outputs(std::span<const std::byte> outputs) const {
    if (write_ != nullptr) write_(outputs, context_);
  }

  [[nodiscard]] constexpr void* context() const noexcept { return context_; }

  /// The input bits it writes: none without a read function, else the windows given, else any
  /// (any_input).
  [[nodiscard]] constexpr std::span<const image_window> input_footprint() const noexcept {
    if (read_ == nullptr) return {};
    if (!inputs_.empty()) return inputs_;
    return detail::any_input_footprint;
  }

 private:
  read_function read_ = nullptr;
  write_function write_ = nullptr;
  void* context_ = nullptr;
  std::span<const image_window> inputs_{};
};

/**
 * A simulated field for tests and simulations: it holds the "physical" input values, which
 * read_inputs() copies into the image at the start of a cycle, and keeps the outputs the
 * last write_outputs() sent.
 *
 *     simulated_io<> field;
 *     field.set<"%IX0.5">(TRUE);          // the sensor at input bit 0.5 turns on
 *     field.set<"%IW2">(INT(300));        // an analogue input
 *     ... run a cycle ...
 *     CHECK(field.output<"%QX0.0">());    // what the program switched on
 *     CHECK(field.get<INT, "%QW4">() == 42);
 *
 * Addresses are checked as located variables' are (the value's type must fit the width,
 * the address must lie inside the image `Image`).
 *
 * It writes the whole input area, or only the window it is given: the field's terminals, where
 * another driver of an io_chain (a Modbus server) writes the rest of the inputs.
 *
 *     simulated_io<> field{window_of<"%IB0", 4>};   // the station's terminals, %IB0..%IB3
 */
template <class Image = default_process_image>
class simulated_io {
  static_assert(detail::is_process_image<Image>::value,
                "iecoop: simulated_io<Image> simulates the field of a process_image<...>");

 public:
  using image_type = Image;

  /// A field over the whole input area.
  constexpr simulated_io() noexcept = default;
  /// A field over the input bits `inputs` (window_of<"%IB0", 4, Image>), the only ones its
  /// read_inputs() writes. A window that is no run of Image's inputs reports
  /// fault_kind::invalid_value, and the field has the whole input area.
  explicit constexpr simulated_io(image_window inputs) noexcept {
    if (inputs.area != io_area::input || inputs.empty() ||
        std::uint64_t{inputs.first_bit} + inputs.bits > std::uint64_t{Image::input_bytes} * 8u) {
      fault(fault_kind::invalid_value,
            "simulated_io: its input window is no run of the image's inputs; give one such as "
            "window_of<\"%IB0\", 4, Image>");
      return;
    }
    window_ = inputs;
  }

  /// Sets the field value of input A (%I): `set<"%IX0.5">(TRUE)`, `set<"%IW2">(INT(300))`,
  /// `set<"%IX0.2">(tPulse.Q)` (a variable wrapper gives its value). The program sees it after
  /// the next read_inputs().
  template <detail::fixed_string A, class V>
  void set(const V& given) noexcept {
    using T = detail::unwrapped_t<const V&>;
    const T value = detail::value_of(given);
    constexpr io_address address = address_of<A>;
    static_assert(
        !detail::address_parses<A> || address.area == io_area::input,
        "iecoop: simulated_io::set<> sets an input (%I...) of the field; outputs (%Q) are written by the program "
        "and memory (%M) is not I/O: read them with get<T, \"%Q...\">(), or use Image::write<T, A>()");
    static_assert(sizeof(detail::access_check_t<T, A, Image>) > 0);  // its static_asserts report misuse
    if constexpr (detail::access_valid<T, A, Image> && address.area == io_area::input) {
      detail::image_store<T, address, Image::mode>(inputs_.data(), value);
      constexpr std::uint64_t first = address.first_bit(Image::mode);
      if (first < window_.first_bit || first + address.bit_count() > std::uint64_t{window_.first_bit} + window_.bits) {
        fault(fault_kind::invalid_value,
              "simulated_io::set: the input lies outside the field's input window, so it never reaches the "
              "image; set an input of the window, or give the field a window that holds it");
      }
    }
  }

  /// The value at A as the field sees it: for %I the value set, for %Q the value the last
  /// write_outputs() sent.
  template <class T, detail::fixed_string A>
  [[nodiscard]] T get() const noexcept {
    constexpr io_address address = address_of<A>;
    static_assert(!detail::address_parses<A> || address.area != io_area::memory,
                  "iecoop: memory (%M) is not connected to the field; read it through the process image, "
                  "Image::read<T, \"%M...\">()");
    static_assert(sizeof(detail::access_check_t<T, A, Image>) > 0);  // its static_asserts report misuse
    if constexpr (detail::access_valid<T, A, Image> && address.area == io_area::input) {
      return detail::image_load<T, address, Image::mode>(inputs_.data());
    } else if constexpr (detail::access_valid<T, A, Image> && address.area == io_area::output) {
      return detail::image_load<T, address, Image::mode>(outputs_.data());
    } else {
      return T{};
    }
  }

  /// The output A as the last write_outputs() sent it, as the default type of its width
  /// (BOOL for %QX, BYTE, WORD, DWORD, LWORD): `output<"%QX0.0">()`.
  template <detail::fixed_string A>
  [[nodiscard]] auto output() const noexcept {
    constexpr io_address address = address_of<A>;
    static_assert(!detail::address_parses<A> || address.area == io_area::output,
                  "iecoop: simulated_io::output<> reads an output (%Q...); read inputs with get<T, \"%I...\">()");
    using T = detail::default_type_t<address.width>;
    if constexpr (address.area == io_area::output) {
      return get<T, A>();
    } else {
      return T{};
    }
  }

  /// IoDriver: copies the field's inputs into the image's input bytes (those of its window).
  void read_inputs(std::span<std::byte> inputs) noexcept {
    if (window_ == whole_inputs) {
      copy_bytes(inputs.data(), inputs.size(), inputs_.data(), inputs_.size());
    } else if (inputs.size() >= inputs_.size()) {
      copy_window(inputs, inputs_, window_);
    }
    ++reads_;
  }
  /// IoDriver: keeps the outputs the program wrote.
  void write_outputs(std::span<const std::byte> outputs) noexcept {
    copy_bytes(outputs_.data(), outputs_.size(), outputs.data(), outputs.size());
    ++writes_;
  }

  /// How often read_inputs() / write_outputs() were called.
  [[nodiscard]] std::size_t read_count() const noexcept { return reads_; }
  [[nodiscard]] std::size_t write_count() const noexcept { return writes_; }

  /// The field's input bytes and the outputs last written.
  [[nodiscard]] std::span<const std::byte, Image::input_bytes> field_inputs() const noexcept { return inputs_; }
  [[nodiscard]] std::span<const std::byte, Image::output_bytes> last_outputs() const noexcept { return outputs_; }

  /// The input bits read_inputs() writes: its window, or the whole area.
  [[nodiscard]] std::span<const image_window> input_footprint() const noexcept { return {&window_, 1}; }
  /// The output bits it keeps: all.
  static constexpr std::array<image_window, 1> output_footprint() noexcept {
    return {image_window{io_area::output, 0, static_cast<std::uint32_t>(Image::output_bytes * 8)}};
  }

  /// Sets every input and output to 0 and the counters to 0.
  void clear() noexcept {
    inputs_.fill(std::byte{0});
    outputs_.fill(std::byte{0});
    reads_ = 0;
    writes_ = 0;
  }

 private:
  static constexpr image_window whole_inputs{io_area::input, 0, static_cast<std::uint32_t>(Image::input_bytes * 8)};
  /// Copies as many bytes as both sides hold (none: no call, as memcpy must not see a null pointer).
  static void copy_bytes(std::byte* to, std::size_t to_size, const std::byte* from, std::size_t from_size) noexcept {
    const std::size_t count = to_size < from_size ? to_size : from_size;
    if (count != 0) std::memcpy(to, from, count);
  }

  std::array<std::byte, Image::input_bytes> inputs_{};
  std::array<std::byte, Image::output_bytes> outputs_{};
  image_window window_ = whole_inputs;
  std::size_t reads_ = 0;
  std::size_t writes_ = 0;
};

/**
 * Several drivers as one: read_inputs() calls the drivers' in the order given, write_outputs()
 * calls them in the same order. It refers to the drivers, which must outlive it.
 *
 *     io_chain io{local_card, modbus_server, remote_io};
 *     plc.connect(io);
 *
 * No two of them may write the same input bits, as two devices of a CODESYS project have
 * addresses of their own: each driver's input footprint (input_footprint(), see
 * <iecoop/io/footprint.hpp>) is checked against the others'. Where two footprints are known
 * while compiling (`static constexpr`, or none declared), a clash does not compile; otherwise
 * configuration_error() tells it, and the application's start() refuses to start with it
 * (fault_kind::invalid_value, naming the drivers and the addresses). A driver that declares no
 * input footprint may write any input byte: it can share a chain only with drivers that write
 * no inputs. Give all drivers to one io_chain (a chain declares no footprint of its own).
 */
template <IoDriver... D>
class io_chain {
  static_assert(sizeof...(D) > 0, "iecoop: io_chain chains at least one driver; give the drivers, io_chain{a, b}");

 public:
  explicit constexpr io_chain(D&... drivers) noexcept : drivers_{&drivers...} {
    (detail::check_footprint_form<D>(), ...);
    static_assert(sizeof(detail::footprint_report_t<D...>) > 0);  // a clash of drivers is reported by that type
  }

  void read_inputs(std::span<std::byte> inputs) {
    std::apply([&](D*... d) { (d->read_inputs(inputs), ...); }, drivers_);
  }
  void write_outputs(std::span<const std::byte> outputs) {
    std::apply([&](D*... d) { (d->write_outputs(outputs), ...); }, drivers_);
  }

  /// nullptr, or why the chain must not run: a driver's own configuration_error(), or two
  /// drivers that write the same input bits ("iecoop: io_chain: drivers 1 (local_card) and 2
  /// (modbus_server) both write %IB0..%IB3; give each driver its own input area"). The text
  /// lives as long as the chain.
  [[nodiscard]] const char* configuration_error() const noexcept {
    const char* own = nullptr;
    std::apply([&](D*... d) { ((own = own != nullptr ? own : detail::configuration_error_of(*d)), ...); }, drivers_);
    if (own != nullptr) return own;
    const std::array<std::span<const image_window>, sizeof...(D)> footprints =
        std::apply([](D*... d) { return std::array{detail::input_footprint_of(*d)...}; }, drivers_);
    const detail::footprint_clash clash =
        detail::first_clash(footprints, [](std::size_t, std::size_t) { return true; });
    if (!clash.found()) return nullptr;
    detail::text_builder text{message_.data(), message_.size()};
    detail::write_clash(text, clash, names[clash.first], names[clash.second]);
    return message_.data();
  }

 private:
  static constexpr std::array<std::string_view, sizeof...(D)> names{detail::driver_name<D>()...};

  std::tuple<D*...> drivers_;
  mutable std::array<char, 320> message_{};  // configuration_error()'s text
};

static_assert(IoDriver<no_io>);
static_assert(IoDriver<callback_io>);
static_assert(IoDriver<simulated_io<>>);
static_assert(IoDriver<io_chain<no_io, callback_io>>);

}  // namespace iecoop

#include <iecoop/detail/pop_macros.hpp>
