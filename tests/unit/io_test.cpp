// The pluggable I/O: the IoDriver concept, simulated_io (a simulated field), callback_io
// (function pointers for real hardware) and no_io, each driving a process image through
// task cycles as the scheduler does (inputs latched at the start, outputs sent at the end).
#include "iecoop_test.hpp"

#include <iecoop/io/driver.hpp>
#include <iecoop/io/located.hpp>

#include <array>
#include <cstddef>
#include <span>
#include <type_traits>

using namespace iecoop;

namespace {

static_assert(IoDriver<no_io>);
static_assert(IoDriver<callback_io>);
static_assert(IoDriver<simulated_io<>>);
static_assert(!IoDriver<int>);
struct read_only_driver {
  void read_inputs(std::span<std::byte>) {}
};
static_assert(!IoDriver<read_only_driver>);

/// One task cycle, as the scheduler runs it.
template <class Image, IoDriver Driver, class Body>
void cycle(Driver& driver, Body body) {
  driver.read_inputs(Image::inputs());
  body();
  driver.write_outputs(Image::outputs());
}

struct sim_tag;
using sim_image = process_image<8, 8, 16, addressing::codesys, sim_tag>;

// A conveyor: start/stop buttons, a speed setpoint, a motor and a speed output.
struct PRG_Conveyor {
  [[no_unique_address]] located<BOOL, "%IX0.0", sim_image> bStartButton;
  [[no_unique_address]] located<BOOL, "%IX0.1", sim_image> bStopButton;
  [[no_unique_address]] located<INT, "%IW1", sim_image> iSpeedSetpoint;
  [[no_unique_address]] located<BOOL, "%QX0.0", sim_image> bMotor;
  [[no_unique_address]] located<INT, "%QW1", sim_image> iMotorSpeed;
  [[no_unique_address]] located<UINT, "%MW0", sim_image> uCycles;
  using LOCATED = pins<&PRG_Conveyor::bStartButton, &PRG_Conveyor::bStopButton, &PRG_Conveyor::iSpeedSetpoint,
                       &PRG_Conveyor::bMotor, &PRG_Conveyor::iMotorSpeed, &PRG_Conveyor::uCycles>;

  void body() {
    // bMotor := (bStartButton OR bMotor) AND NOT bStopButton;
    bMotor = (bStartButton | bMotor) & !bStopButton;
    if (bMotor) {
      iMotorSpeed = iSpeedSetpoint * INT(2);
    } else {
      iMotorSpeed = 0;
    }
    ++uCycles;
  }
};

}  // namespace

TEST_SUITE("I/O drivers") {
  TEST_CASE("simulated_io: the field's inputs reach the program, its outputs reach the field") {
    check_located<PRG_Conveyor>();
    sim_image::clear();
    simulated_io<sim_image> field;
    PRG_Conveyor prg;

    field.set<"%IW1">(INT(300));
    cycle<sim_image>(field, [&] { prg.body(); });
    CHECK(field.output<"%QX0.0">() == FALSE);
    CHECK(field.get<INT, "%QW1">() == 0);

    field.set<"%IX0.0">(TRUE);  // press start
    cycle<sim_image>(field, [&] { prg.body(); });
    CHECK(field.output<"%QX0.0">() == TRUE);
    CHECK(field.get<INT, "%QW1">() == 600);
    CHECK(field.output<"%QW1">() == WORD(600));  // the default type of a word: WORD
    static_assert(std::is_same_v<decltype(field.output<"%QX0.0">()), BOOL>);
    static_assert(std::is_same_v<decltype(field.output<"%QB0">()), BYTE>);
    static_assert(std::is_same_v<decltype(field.output<"%QD1">()), DWORD>);

    field.set<"%IX0.0">(FALSE);  // release start: the motor holds itself
    field.set<"%IW1">(INT(-10));
    cycle<sim_image>(field, [&] { prg.body(); });
    CHECK(field.output<"%QX0.0">() == TRUE);
    CHECK(field.get<INT, "%QW1">() == -20);

    field.set<"%IX0.1">(TRUE);  // press stop
    cycle<sim_image>(field, [&] { prg.body(); });
    CHECK(field.output<"%QX0.0">() == FALSE);
    CHECK(field.get<INT, "%QW1">() == 0);

    CHECK(field.read_count() == 4u);
    CHECK(field.write_count() == 4u);
    CHECK(prg.uCycles == 4u);
    CHECK(field.get<BOOL, "%IX0.1">() == TRUE);  // an input reads back as set
    CHECK(field.get<INT, "%IW1">() == -10);
  }

  TEST_CASE("simulated_io: set<> takes a variable wrapper's value, such as a block's output") {
    sim_image::clear();
    simulated_io<sim_image> field;
    TP pulse;  // a simulated sensor: a pulse of T#5ms
    cycle_clock::set(LTIME{});
    pulse("IN"_ = TRUE, "PT"_ = 5);
    field.set<"%IX0.0">(pulse.Q);  // pulse.Q is the block's VAR_OUTPUT wrapper
    CHECK(field.get<BOOL, "%IX0.0">() == TRUE);
    cycle_clock::set(LTIME(TIME(5)));
    pulse();
    field.set<"%IX0.0">(pulse.Q);
    CHECK(field.get<BOOL, "%IX0.0">() == FALSE);
  }

  TEST_CASE("simulated_io: inputs are latched, not seen before the next cycle") {
    sim_image::clear();
    simulated_io<sim_image> field;
    PRG_Conveyor prg;
    field.set<"%IX0.0">(TRUE);
    CHECK(prg.bStartButton == FALSE);  // the image has not read the field yet
    field.read_inputs(sim_image::inputs());
    CHECK(prg.bStartButton == TRUE);
    field.set<"%IX0.0">(FALSE);  // changes during the cycle stay in the field
    CHECK(prg.bStartButton == TRUE);
    prg.body();
    CHECK(field.output<"%QX0.0">() == FALSE);  // nor do outputs reach it before write_outputs
    field.write_outputs(sim_image::outputs());
    CHECK(field.output<"%QX0.0">() == TRUE);
  }

  TEST_CASE("simulated_io: raw bytes, every size, little-endian, clear()") {
    simulated_io<sim_image> field;
    field.set<"%IB0">(BYTE(0xA5));
    field.set<"%IX1.7">(TRUE);
    field.set<"%ID1">(DINT(-2));
    CHECK(std::to_integer<unsigned>(field.field_inputs()[0]) == 0xA5u);
    CHECK(std::to_integer<unsigned>(field.field_inputs()[1]) == 0x80u);
    CHECK(std::to_integer<unsigned>(field.field_inputs()[4]) == 0xFEu);
    CHECK(std::to_integer<unsigned>(field.field_inputs()[7]) == 0xFFu);
    CHECK(field.get<BOOL, "%IX0.0">() == TRUE);
    CHECK(field.get<BOOL, "%IX0.1">() == FALSE);
    CHECK(field.get<UDINT, "%ID1">() == 0xFFFFFFFEu);

    struct big_tag;
    using big_image = process_image<16, 16, 0, addressing::codesys, big_tag>;
    simulated_io<big_image> wide_field;
    wide_field.set<"%IL1">(LREAL(0.25));
    wide_field.set<"%ID1">(REAL(-1.0f));
    wide_field.set<"%IW0">(UINT(65535));
    wide_field.read_inputs(big_image::inputs());
    CHECK(big_image::read<LREAL, "%IL1">() == 0.25);
    CHECK(big_image::read<REAL, "%ID1">() == -1.0f);
    CHECK(big_image::read<UINT, "%IW0">() == 65535u);
    big_image::write<LTIME, "%QL0">("LTIME#1s"_iec);
    big_image::write<TIME, "%QD2">("T#5m"_iec);
    wide_field.write_outputs(big_image::outputs());
    CHECK(wide_field.get<LTIME, "%QL0">() == "LTIME#1s"_iec);
    CHECK(wide_field.get<TIME, "%QD2">() == "T#5m"_iec);
    CHECK(std::to_integer<unsigned>(wide_field.last_outputs()[8]) == 0xE0u);  // 300000 = 0x000493E0

    wide_field.clear();
    CHECK(wide_field.get<LREAL, "%IL1">() == 0.0);
    CHECK(wide_field.get<TIME, "%QD2">() == TIME());
    CHECK(wide_field.read_count() == 0u);
    CHECK(wide_field.write_count() == 0u);
  }

  TEST_CASE("simulated_io copies what both sides have when the spans differ in size") {
    simulated_io<sim_image> field;
    field.set<"%IB7">(BYTE(9));
    field.set<"%IB0">(BYTE(1));
    std::array<std::byte, 4> small_inputs{};
    field.read_inputs(small_inputs);
    CHECK(std::to_integer<unsigned>(small_inputs[0]) == 1u);
    std::array<std::byte, 32> large_inputs{};
    field.read_inputs(large_inputs);
    CHECK(std::to_integer<unsigned>(large_inputs[7]) == 9u);
    CHECK(std::to_integer<unsigned>(large_inputs[8]) == 0u);
    std::array<std::byte, 2> few_outputs{std::byte{3}, std::byte{4}};
    field.write_outputs(few_outputs);
    CHECK(field.output<"%QB1">() == 4);
    CHECK(field.output<"%QB2">() == 0);
  }

  TEST_CASE("callback_io: function pointers and a context, both ways") {
    struct board {
      std::array<std::byte, 2> pins_in{std::byte{0x03}, std::byte{0x80}};
      std::array<std::byte, 2> pins_out{};
      int reads = 0;
    };
    board hw;
    callback_io io{[](std::span<std::byte> inputs, void* context) {
                     auto& b = *static_cast<board*>(context);
                     for (std::size_t i = 0; i < b.pins_in.size() && i < inputs.size(); ++i) inputs[i] = b.pins_in[i];
                     ++b.reads;
                   },
                   [](std::span<const std::byte> outputs, void* context) {
                     auto& b = *static_cast<board*>(context);
                     for (std::size_t i = 0; i < b.pins_out.size() && i < outputs.size(); ++i)
                       b.pins_out[i] = outputs[i];
                   },
                   &hw};
    CHECK(io.context() == &hw);

    sim_image::clear();
    PRG_Conveyor prg;
    cycle<sim_image>(io, [&] { prg.body(); });  // start (IX0.0) and stop (IX0.1) both pressed: stop wins
    CHECK(hw.reads == 1);
    CHECK(prg.bStartButton == TRUE);
    CHECK(prg.bStopButton == TRUE);
    CHECK(prg.iSpeedSetpoint == 0);  // %IW1 is bytes 2..3, which the board does not have: they stay 0
    CHECK(hw.pins_out[0] == std::byte{0});

    hw.pins_in[0] = std::byte{0x01};  // release stop
    cycle<sim_image>(io, [&] { prg.body(); });
    CHECK(hw.pins_out[0] == std::byte{0x01});  // the motor runs
    CHECK(hw.reads == 2);
  }

  TEST_CASE("callback_io without functions, and no_io, do nothing") {
    sim_image::clear();
    sim_image::write<BYTE, "%IB0">(BYTE(0x42));
    callback_io unset;
    unset.read_inputs(sim_image::inputs());
    unset.write_outputs(sim_image::outputs());
    CHECK(sim_image::read<BYTE, "%IB0">() == 0x42);
    callback_io read_only{[](std::span<std::byte> inputs, void*) { inputs[0] = std::byte{7}; }, nullptr};
    read_only.read_inputs(sim_image::inputs());
    read_only.write_outputs(sim_image::outputs());
    CHECK(sim_image::read<BYTE, "%IB0">() == 7);

    no_io none;
    cycle<sim_image>(none, [] {});
    CHECK(sim_image::read<BYTE, "%IB0">() == 7);  // inputs keep their values
    static_assert(std::is_empty_v<no_io>);
  }
}
