// The application and the process image: inputs latched at the start of each task cycle,
// the outputs a cycle changed written at its end (bit by bit, per task), located variables
// in programs, and the I/O drivers.
#include "iecoop_test.hpp"

#include <iecoop/runtime/application.hpp>

#include <vector>

using namespace iecoop;

namespace {

// An image of its own, so that no other test's values leak in.
struct io_test_tag {};
using image = process_image<8, 8, 8, addressing::codesys, io_test_tag>;
template <class T, fixed_string A>  // iecoop::fixed_string: a literal as a template argument
using at_ = located<T, A, image>;

// PROGRAM LATCH_PRG: copies a start button to a motor output and counts the cycles it saw
// the button pressed; reads the input twice per cycle.
struct LATCH_PRG : program<LATCH_PRG> {
  [[no_unique_address]] at_<BOOL, "%IX0.0"> bStart;
  [[no_unique_address]] at_<INT, "%IW1"> iSpeed;
  [[no_unique_address]] at_<BOOL, "%QX0.0"> bMotor;
  [[no_unique_address]] at_<INT, "%QW1"> iReference;
  using LOCATED = pins<&LATCH_PRG::bStart, &LATCH_PRG::iSpeed, &LATCH_PRG::bMotor, &LATCH_PRG::iReference>;

  var<INT> nPressed;
  std::vector<INT> speeds;
  void body() {
    if (bStart) nPressed = nPressed + 1;
    speeds.push_back(iSpeed);
    bMotor = bStart;
    iReference = iSpeed * 2;
  }
};

// Two programs writing different bits of output byte 0, in tasks of different priorities.
struct BIT0_PRG : program<BIT0_PRG> {
  [[no_unique_address]] at_<BOOL, "%QX0.0"> bOut;
  using LOCATED = pins<&BIT0_PRG::bOut>;
  void body() { bOut = !bOut; }
};
struct BIT1_PRG : program<BIT1_PRG> {
  [[no_unique_address]] at_<BOOL, "%QX0.1"> bOut;
  using LOCATED = pins<&BIT1_PRG::bOut>;
  void body() { bOut = !bOut; }
};

LTIME ms(std::uint64_t n) { return LTIME::from_ticks(n * 1000000U); }

// An image of 11 output bytes (one word and three bytes: the staging compares both ways), for
// programs that change their outputs in some cycles only.
struct io_test_odd_tag {};
using odd_image = process_image<4, 11, 4, addressing::codesys, io_test_odd_tag>;

// PROGRAM SOMETIMES_PRG: toggles %QX0.0 in its first three cycles and counts %QB10 up in
// cycles 5 and 6, and changes no output in the others.
struct SOMETIMES_PRG : program<SOMETIMES_PRG> {
  [[no_unique_address]] located<BOOL, "%QX0.0", odd_image> bOut;
  [[no_unique_address]] located<BYTE, "%QB10", odd_image> nLast;
  using LOCATED = pins<&SOMETIMES_PRG::bOut, &SOMETIMES_PRG::nLast>;
  var<INT> nCycle;
  void body() {
    if (nCycle < 3) bOut = !bOut;
    if (nCycle == 5 || nCycle == 6) nLast = nLast + 1;
    nCycle = nCycle + 1;
  }
};
// PROGRAM SLOW_BIT_PRG: sets %QX0.1 (in a cycle that takes time).
struct SLOW_BIT_PRG : program<SLOW_BIT_PRG> {
  [[no_unique_address]] located<BOOL, "%QX0.1", odd_image> bOut;
  using LOCATED = pins<&SLOW_BIT_PRG::bOut>;
  void body() { bOut = TRUE; }
};

}  // namespace

TEST_SUITE("application: process image") {
  TEST_CASE("inputs are latched at the start of each task cycle") {
    application plc{task<LATCH_PRG>{"Io", cyclic{"T#10ms"_iec}, 0}, use_image<image>{}};
    simulated_io<image> field;
    plc.connect(field);
    plc.start();
    plc.run_for(ms(10));
    CHECK(field.read_count() == 1);
    field.set<"%IX0.0">(TRUE);
    field.set<"%IW1">(INT(21));
    CHECK(image::read<BOOL, "%IX0.0">() == FALSE);  // the image holds what the last cycle latched
    plc.run_for(ms(10));
    CHECK(image::read<BOOL, "%IX0.0">() == TRUE);
    CHECK(LATCH_PRG::instance().nPressed == 1);
    CHECK(LATCH_PRG::instance().speeds == std::vector<INT>{0, 21});
    CHECK(field.read_count() == 2);
  }

  TEST_CASE("the outputs of a cycle reach the field at its end") {
    // The cycle at 0 ms takes 3 ms: its program sets the motor at 0 ms, the field sees it at 3 ms.
    application plc{task<LATCH_PRG>{"Io", cyclic{"T#10ms"_iec}, 0}, use_image<image>{}};
    simulated_io<image> field;
    plc.connect(field);
    plc.task(0).model_execution_time(ms(3));
    field.set<"%IX0.0">(TRUE);
    field.set<"%IW1">(INT(100));
    plc.start();
    plc.run_for(ms(3));
    CHECK(image::read<BOOL, "%QX0.0">() == TRUE);  // written by the program
    CHECK(field.output<"%QX0.0">() == FALSE);      // not yet sent
    CHECK(field.write_count() == 0);
    plc.run_for(ms(1));
    CHECK(field.output<"%QX0.0">() == TRUE);
    CHECK(field.get<INT, "%QW1">() == 200);
    CHECK(field.write_count() == 1);
    CHECK(plc.published_outputs()[0] == std::byte{1});
  }

  TEST_CASE("each task writes the output bits its own cycle changed") {
    // BIT1 (every 10 ms, 4 ms long, priority 5) and BIT0 (every 1 ms, 0.5 ms, priority 0)
    // toggle bits 1 and 0 of output byte 0. BIT1's toggle at 0 ms reaches the field only
    // when its cycle ends, although BIT0's cycles end (and write) in between.
    application plc{task<BIT1_PRG>{"Slow", cyclic{"T#10ms"_iec}, 5}, task<BIT0_PRG>{"Fast", cyclic{"T#1ms"_iec}, 0},
                    use_image<image>{}};
    simulated_io<image> field;
    plc.connect(field);
    plc.task("Slow").model_execution_time(ms(4));
    plc.task("Fast").model_execution_time(LTIME::from_ticks(500000));
    plc.start();
    // 0-0.5 Fast (bit0 := 1) | 0.5-1 Slow (bit1 := 1, 3.5 ms left) | 1-1.5 Fast (bit0 := 0) | ...
    plc.run_for(ms(1));
    CHECK(field.output<"%QX0.0">() == TRUE);
    CHECK(field.output<"%QX0.1">() == FALSE);
    CHECK(image::read<BOOL, "%QX0.1">() == TRUE);  // Slow's program ran at 0.5 ms
    plc.run_for(ms(1));
    CHECK(field.output<"%QX0.0">() == FALSE);
    CHECK(field.output<"%QX0.1">() == FALSE);  // still not: Slow's cycle has not ended
    // Slow gets 0.5 ms per millisecond: 0.5 + 7 x 0.5 = 4 ms of work, done at 8 ms.
    plc.run_for(ms(6));  // up to 8 ms, excluded
    CHECK(field.output<"%QX0.1">() == FALSE);
    plc.run_for(ms(1));
    CHECK(field.output<"%QX0.1">() == TRUE);
    CHECK(plc.task("Slow").statistics().last_cycle_time == LTIME::from_ticks(7500000));
  }

  TEST_CASE("a cycle that changes no output writes the published outputs unchanged") {
    // Fast (every 1 ms, no execution time) changes outputs in its cycles 0-2 and 5-6 only;
    // Slow (every 100 ms, 4 ms long, lower priority) sets bit 1 in its cycle at 0 ms, which
    // reaches the field at 4 ms although Fast's cycles end and write in between. A byte a
    // test writes into the image between cycles is no cycle's change: it is not published.
    application plc{task<SLOW_BIT_PRG>{"Slow", cyclic{"T#100ms"_iec}, 5},
                    task<SOMETIMES_PRG>{"Fast", cyclic{"T#1ms"_iec}, 0}, use_image<odd_image>{}};
    simulated_io<odd_image> field;
    plc.connect(field);
    plc.task("Slow").model_execution_time(ms(4));
    plc.start();
    const auto published = [&] {
      std::vector<int> bytes;
      for (const std::byte b : plc.published_outputs()) bytes.push_back(std::to_integer<int>(b));
      return bytes;
    };
    std::vector<std::vector<int>> seen;  // after each millisecond
    for (int k = 0; k < 8; ++k) {
      if (k == 3) odd_image::write<BYTE, "%QB5">(BYTE(0x5A));  // between cycles, by hand
      plc.run_for(ms(1));
      seen.push_back(published());
      CHECK(field.write_count() == static_cast<std::size_t>(k + 1 + (k >= 4 ? 1 : 0)));  // + Slow's end
    }
    //               QB0 (bit 0 Fast, bit 1 Slow)    QB10
    const std::vector<std::vector<int>> expected{
        {1, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0},  // 0 ms: Fast's cycle 0
        {0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0},  // 1 ms: cycle 1
        {1, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0},  // 2 ms: cycle 2
        {1, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0},  // 3 ms: cycle 3 changes nothing
        {3, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0},  // 4 ms: Slow's cycle ends
        {3, 0, 0, 0, 0, 0, 0, 0, 0, 0, 1},  // 5 ms: cycle 5
        {3, 0, 0, 0, 0, 0, 0, 0, 0, 0, 2},  // 6 ms: cycle 6
        {3, 0, 0, 0, 0, 0, 0, 0, 0, 0, 2},  // 7 ms: nothing
    };
    CHECK(seen == expected);
    CHECK(field.output<"%QX0.1">() == TRUE);
    CHECK(field.get<BYTE, "%QB10">() == 2);
    CHECK(field.get<BYTE, "%QB5">() == 0);
    CHECK(plc.task("Fast").statistics().cycles == 8);
  }

  TEST_CASE("a callback_io connects the application to hand-written I/O") {
    struct hardware {
      std::byte inputs[8]{};
      std::byte outputs[8]{};
      int reads = 0;
    } board;
    board.inputs[0] = std::byte{1};  // start pressed
    board.inputs[2] = std::byte{7};  // %IW1 = 7 (little-endian)
    callback_io io{[](std::span<std::byte> in, void* c) {
                     auto* b = static_cast<hardware*>(c);
                     ++b->reads;
                     for (std::size_t i = 0; i < in.size(); ++i) in[i] = b->inputs[i];
                   },
                   [](std::span<const std::byte> out, void* c) {
                     auto* b = static_cast<hardware*>(c);
                     for (std::size_t i = 0; i < out.size(); ++i) b->outputs[i] = out[i];
                   },
                   &board};
    application plc{task<LATCH_PRG>{"Io", cyclic{"T#10ms"_iec}, 0}, use_image<image>{}};
    plc.connect(io);
    plc.start();
    plc.run_for(ms(20));
    CHECK(board.reads == 2);
    CHECK(board.outputs[0] == std::byte{1});
    CHECK(board.outputs[2] == std::byte{14});
  }

  TEST_CASE("without a driver the image keeps what a test writes into it") {
    application plc{task<LATCH_PRG>{"Io", cyclic{"T#10ms"_iec}, 0}, use_image<image>{}};
    plc.start();  // clears the image
    image::write<BOOL, "%IX0.0">(TRUE);
    plc.run_for(ms(10));
    CHECK(LATCH_PRG::instance().nPressed == 1);
    CHECK(image::read<BOOL, "%QX0.0">() == TRUE);
  }

  TEST_CASE("start and reset clear the process image") {
    application plc{task<LATCH_PRG>{"Io", cyclic{"T#10ms"_iec}, 0}, use_image<image>{}};
    image::write<BYTE, "%MB3">(BYTE(9));
    plc.start();
    CHECK(image::read<BYTE, "%MB3">() == 0);
    image::write<BYTE, "%MB3">(BYTE(9));
    plc.reset(reset_kind::warm);
    CHECK(image::read<BYTE, "%MB3">() == 0);
  }
}
