// What an I/O driver touches in the process image (<iecoop/io/footprint.hpp>): windows of
// addresses, the drivers' declared input footprints, and io_chain's refusal of two drivers that
// write the same input bits — at the application's start(), through the fault path, where the
// footprints are known only at run time (the compile-time refusals are compile-fail tests:
// io_chain_inputs_overlap, io_chain_footprint_undeclared, io_footprint_form).
#include "iecoop_test.hpp"

#include <iecoop/io/driver.hpp>
#include <iecoop/io/footprint.hpp>
#include <iecoop/runtime/application.hpp>

#include <array>
#include <cstddef>
#include <span>
#include <string>

using namespace iecoop;
using iecoop_test::fault_recorder;

namespace {

struct footprint_tag {};
using image = process_image<16, 8, 8, addressing::codesys, footprint_tag>;
using twincat_image = process_image<32, 8, 8, addressing::byte_offset, footprint_tag>;

// window_of<First, Count, Image>: Count values of First's width, in Image's addressing.
static_assert(window_of<"%IB0", 4> == image_window{io_area::input, 0, 32});
static_assert(window_of<"%IX0.4", 3> == image_window{io_area::input, 4, 3});
static_assert(window_of<"%IW8", 8> == image_window{io_area::input, 128, 128});                // CODESYS: bytes 16..31
static_assert(window_of<"%IW8", 8, twincat_image> == image_window{io_area::input, 64, 128});  // bytes 8..23
static_assert(window_of<"%QD1", 1, image> == image_window{io_area::output, 32, 32});
static_assert(window_of<"%IB15", 1, image>.end_byte() == 16);  // the last byte of the image fits

// The drivers' declarations.
static_assert(detail::static_input_footprint<no_io>);
static_assert(no_io::input_footprint().empty());
static_assert(!detail::static_input_footprint<callback_io>);
static_assert(detail::runtime_input_footprint<callback_io>);
static_assert(detail::runtime_input_footprint<simulated_io<image>>);

// A local card known while compiling: push-buttons in %IB0, selector switches in %IB1.
struct local_card {
  static constexpr std::array<image_window, 2> input_footprint() noexcept {
    return {window_of<"%IB0", 1, image>, window_of<"%IB1", 1, image>};
  }
  static constexpr std::array<image_window, 1> output_footprint() noexcept { return {window_of<"%QB0", 1, image>}; }
  void read_inputs(std::span<std::byte> in) noexcept {
    in[0] = std::byte{0x05};
    in[1] = std::byte{0x30};
  }
  void write_outputs(std::span<const std::byte>) noexcept {}
};
static_assert(detail::static_input_footprint<local_card>);

// An analogue card whose channels are configured at run time.
struct analogue_card {
  std::array<image_window, 1> channels{};
  [[nodiscard]] std::span<const image_window> input_footprint() const noexcept { return channels; }
  void read_inputs(std::span<std::byte> in) noexcept { copy_window(in, raw, channels[0]); }
  void write_outputs(std::span<const std::byte>) noexcept {}
  std::array<std::byte, image::input_bytes> raw{};
};

// A driver of old, which says nothing about what it writes.
struct silent_card {
  void read_inputs(std::span<std::byte> in) noexcept { in[2] = std::byte{1}; }
  void write_outputs(std::span<const std::byte>) noexcept {}
};

void read_gpio(std::span<std::byte> in, void*) { in[0] = std::byte{0xFF}; }
void write_gpio(std::span<const std::byte>, void*) {}

// PROGRAM CHAIN_PRG: counts its cycles.
struct CHAIN_PRG : program<CHAIN_PRG> {
  UDINT udiCycles;
  void body() { udiCycles = udiCycles + 1; }
};

LTIME ms(std::uint64_t n) { return LTIME::from_ticks(n * 1000000U); }

}  // namespace

TEST_SUITE("I/O footprints") {
  TEST_CASE("window_of and the windows' text: whole bytes as %IB, bits as %IX") {
    auto text = [](image_window w) {
      std::array<char, 48> buffer{};
      detail::text_builder t{buffer.data(), buffer.size()};
      detail::write_window(t, w);
      return std::string(buffer.data());
    };
    CHECK(text(window_of<"%IB0", 4>) == "%IB0..%IB3");
    CHECK(text(window_of<"%IB7">) == "%IB7");
    CHECK(text(window_of<"%IW8", 8>) == "%IB16..%IB31");
    CHECK(text(window_of<"%IX0.4", 12>) == "%IX0.4..%IX1.7");
    CHECK(text(window_of<"%IX2.3">) == "%IX2.3");
    CHECK(text(window_of<"%QX1.0", 3>) == "%QX1.0..%QX1.2");
    CHECK(detail::shared_bits(window_of<"%IB0", 4>, window_of<"%IW1", 8>) == window_of<"%IB2", 2>);
    CHECK(detail::shared_bits(any_input, window_of<"%IB3", 2>) == window_of<"%IB3", 2>);
    CHECK(detail::shared_bits(window_of<"%IX0.0", 4>, window_of<"%IX0.4", 4>).empty());  // bits of one byte
    CHECK(detail::shared_bits(window_of<"%IB0", 1>, window_of<"%QB0", 1>).empty());      // another area
    CHECK_FALSE(window_of<"%IX0.0", 4>.overlaps(window_of<"%IX0.4", 4>));
    CHECK(any_input.overlaps(window_of<"%IB15">));  // no overflow at the top of the 32 bits
  }

  TEST_CASE("io_chain: drivers on inputs of their own pass, and each writes its own") {
    analogue_card analogue;
    analogue.channels[0] = window_of<"%IW2", 2, image>;  // %IB4..%IB7
    analogue.raw[4] = std::byte{0x2C};
    analogue.raw[0] = std::byte{0xEE};  // not its own: never written
    simulated_io<image> field{window_of<"%IB8", 2, image>};
    field.set<"%IB8">(BYTE(0x11));
    callback_io outputs_only{nullptr, &write_gpio};
    no_io none;
    local_card card;
    io_chain io{card, analogue, field, outputs_only, none};
    CHECK(io.configuration_error() == nullptr);
    image::clear();
    image::write<BYTE, "%IB12">(BYTE(0x77));
    io.read_inputs(image::inputs());
    CHECK(image::read<BYTE, "%IB0">() == 0x05);
    CHECK(image::read<BYTE, "%IB1">() == 0x30);
    CHECK(image::read<BYTE, "%IB4">() == 0x2C);
    CHECK(image::read<BYTE, "%IB8">() == 0x11);
    CHECK(image::read<BYTE, "%IB12">() == 0x77);  // no driver's: left alone, also by the simulated field
  }

  TEST_CASE("io_chain: two drivers on the same input bits, named with the addresses they share") {
    local_card card;
    analogue_card analogue;
    analogue.channels[0] = window_of<"%IX1.4", 8, image>;  // %IX1.4..%IX2.3: the card's %IB1 in part
    io_chain io{card, analogue};
    CHECK(std::string(io.configuration_error()) ==
          "iecoop: io_chain: drivers 1 (local_card) and 2 (analogue_card) both write %IX1.4..%IX1.7; give each driver "
          "its own input area");
    simulated_io<image> whole;  // the whole input area
    io_chain with_field{card, whole};
    CHECK(std::string(with_field.configuration_error()) ==
          "iecoop: io_chain: drivers 1 (local_card) and 2 (simulated_io) both write %IB0; give each driver its own "
          "input area");
  }

  TEST_CASE("io_chain: a driver that declares no input footprint may write any input byte") {
    local_card card;
    callback_io gpio{&read_gpio, &write_gpio};
    io_chain io{card, gpio};
    CHECK(std::string(io.configuration_error()) ==
          "iecoop: io_chain: drivers 1 (local_card) and 2 (callback_io) both write %IB0 (driver 2 declares no input "
          "footprint: it may write any input byte); declare what it writes (input_footprint(), "
          "docs/process-image.md), and give each driver its own input area");
    callback_io other{&read_gpio, &write_gpio};
    io_chain two{gpio, other};
    CHECK(std::string(two.configuration_error()) ==
          "iecoop: io_chain: drivers 1 (callback_io) and 2 (callback_io) may both write any input byte: neither "
          "declares its input footprint; declare what each writes (input_footprint(), docs/process-image.md), and "
          "give each driver its own input area");
    // Declared, the same card passes.
    static constexpr std::array gpio_inputs{window_of<"%IB3", 1, image>};
    callback_io declared{&read_gpio, &write_gpio, nullptr, gpio_inputs};
    CHECK(declared.input_footprint().size() == 1);
    io_chain fine{card, declared};
    CHECK(fine.configuration_error() == nullptr);
    // A silent driver with one that writes no inputs, and alone in a chain.
    silent_card silent;
    no_io none;
    io_chain alone{silent, none};
    CHECK(alone.configuration_error() == nullptr);
    analogue_card unconfigured;  // no channels yet: an empty window
    io_chain beside{silent, unconfigured};
    CHECK(beside.configuration_error() == nullptr);
    unconfigured.channels[0] = window_of<"%IB9", 1, image>;
    CHECK(std::string(beside.configuration_error())
              .find("drivers 1 (silent_card) and 2 (analogue_card) both write %IB9") !=
          std::string::npos);  // checked as the drivers are now
    // A chain in a chain declares no footprint of its own; its own clash comes first.
    io_chain inner{card, gpio};
    no_io spare;
    io_chain outer{inner, spare};
    CHECK(std::string(outer.configuration_error()) == io.configuration_error());
  }

  TEST_CASE("simulated_io with a window writes only its window, and set<> outside it is a fault") {
    simulated_io<image> field{window_of<"%IX0.4", 4, image>};
    CHECK(field.input_footprint()[0] == window_of<"%IX0.4", 4, image>);
    CHECK(simulated_io<image>::output_footprint()[0] == window_of<"%QB0", 8, image>);
    field.set<"%IX0.5">(TRUE);
    image::clear();
    image::write<BYTE, "%IB0">(BYTE(0x0F));  // bits 0..3: another driver's
    field.read_inputs(image::inputs());
    CHECK(image::read<BYTE, "%IB0">() == 0x2F);
    {
      fault_recorder faults;
      field.set<"%IX0.3">(TRUE);
      CHECK(faults.count == 1);
      CHECK(faults.last_kind == fault_kind::invalid_value);
      CHECK(faults.last_message.find("outside the field's input window") != std::string::npos);
      field.set<"%IB1">(BYTE(0xFF));
      CHECK(faults.count == 2);
    }
    image::clear();
    field.read_inputs(image::inputs());
    CHECK(image::read<BYTE, "%IB0">() == 0x20);  // the bits outside never reach the image
    CHECK(image::read<BYTE, "%IB1">() == 0);
    {
      fault_recorder faults;
      simulated_io<image> narrow{window_of<"%IX0.4", 4, image>};
      narrow.set<"%IW0">(INT(1));  // %IX0.0..%IX1.7: wider than the window
      CHECK(faults.count == 1);
    }
    {
      fault_recorder faults;
      simulated_io<image> wrong{window_of<"%QB0", 1, image>};
      CHECK(faults.count == 1);
      CHECK(faults.last_message.find("no run of the image's inputs") != std::string::npos);
      CHECK(wrong.input_footprint()[0] == window_of<"%IB0", 16, image>);  // the whole area, as without a window
      simulated_io<image> too_wide{window_of<"%IB0", 20, process_image<32>>};
      CHECK(faults.count == 2);
    }
  }

  TEST_CASE("the application refuses to start with a chain of two drivers on the same input bits") {
    application plc{task<CHAIN_PRG>{"Io", cyclic{"T#10ms"_iec}, 0}, use_image<image>{}};
    local_card card;
    simulated_io<image> field;  // the whole input area, %IB0 too
    io_chain clash{card, field};
    plc.connect(clash);
    {
      fault_recorder faults;
      CHECK_FALSE(plc.start());
      CHECK(faults.count == 1);
      CHECK(faults.last_kind == fault_kind::invalid_value);
      CHECK(faults.last_message ==
            "iecoop: io_chain: drivers 1 (local_card) and 2 (simulated_io) both write %IB0; give each driver its own "
            "input area");
      CHECK(plc.state() == application_state::stopped);
    }
    simulated_io<image> rest{window_of<"%IB2", 14, image>};
    io_chain fine{card, rest};
    plc.connect(fine);
    REQUIRE(plc.start());
    plc.run_for(ms(20));
    CHECK(plc.get<CHAIN_PRG>().udiCycles == 2);
    CHECK(image::read<BYTE, "%IB0">() == 0x05);
    // While the tasks run, connect() refuses it: the chain connected before stays.
    {
      fault_recorder faults;
      plc.connect(clash);
      CHECK(faults.count == 1);
      CHECK(faults.last_message.find("drivers 1 (local_card) and 2 (simulated_io) both write %IB0") !=
            std::string::npos);
    }
    rest.set<"%IB2">(BYTE(9));
    plc.run_for(ms(10));
    CHECK(image::read<BYTE, "%IB2">() == 9);
    CHECK(plc.get<CHAIN_PRG>().udiCycles == 3);
    // Halted by a reset, start() checks again.
    plc.reset(reset_kind::warm);
    plc.connect(clash);
    {
      fault_recorder faults;
      CHECK_FALSE(plc.start());
      CHECK(faults.count == 1);
      CHECK(plc.state() == application_state::halted);
    }
    plc.connect(fine);
    CHECK(plc.start());
  }
}
