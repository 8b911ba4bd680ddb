// What the test kit's benchmarks run (testing_bench.cpp, testing_count.cpp): a small block
// stepped through time by the kit's drivers and by the hand-written loops they replace.
//
//   kit_cycles       testing::cycles over FB_Blink, one step() per cycle
//   hand_cycles      the loop a test would write instead: cycle_clock::set, the call, time on
//   kit_plc          testing::plc<make_blink<>>, one step() per cycle (one base cycle)
//   app_run_for      the same application without the kit: run_for(base_cycle()) per cycle
//
// The kit includes doctest: exactly one translation unit of a program that includes this
// header defines DOCTEST_CONFIG_IMPLEMENT first (doctest's code, without its main()).
#pragma once

#include <cstdint>

#include <iecoop/iecoop.hpp>
#include <iecoop/testing.hpp>

namespace testing_programs {

using namespace iecoop;

// FUNCTION_BLOCK FB_Blink: bOut toggles every tHalf while bEnable (a TON that restarts itself).
struct FB_Blink : function_block<FB_Blink> {
  BOOL bEnable = TRUE;        // VAR_INPUT bEnable : BOOL := TRUE;
  TIME tHalf = "T#50ms"_iec;  //           tHalf : TIME := T#50ms;
  BOOL bOut;                  // VAR_OUTPUT bOut : BOOL;
  var<UDINT> nToggles;        // VAR nToggles : UDINT;
  TON tonHalf;                //     tonHalf : TON;
  using VAR_INPUT = pins<&FB_Blink::bEnable, &FB_Blink::tHalf>;
  using VAR_OUTPUT = pins<&FB_Blink::bOut>;

  void body() {
    tonHalf("IN"_ = bEnable & ~tonHalf.Q, "PT"_ = tHalf);  // tonHalf(IN := bEnable AND NOT tonHalf.Q, PT := tHalf);
    if (tonHalf.Q) {                                       // IF tonHalf.Q THEN
      bOut = ~bOut;                                        //     bOut := NOT bOut;
      nToggles = nToggles + 1U;                            //     nToggles := nToggles + 1;
    }                                                      // END_IF
  }
};

// PROGRAM BLINK_PRG: calls fbBlink, in task Fast. A program has one instance at a time: two
// applications that live together (the paired benchmarks) run two copies, BLINK_PRG<0> and <1>.
template <int Copy>
struct BLINK_PRG : program<BLINK_PRG<Copy>> {
  FB_Blink fbBlink;
  void body() { fbBlink(); }
};

/// One task, Fast, every 1 ms: BLINK_PRG.
template <int Copy = 0>
auto make_blink() {
  return application{task<BLINK_PRG<Copy>>{"Fast", cyclic{"T#1ms"_iec}, 0}};
}

inline constexpr LTIME cycle_time = LTIME(TIME::from_ticks(1));  // T#1ms

// Makes the compiler assume that memory was read and written here (as benchmark::ClobberMemory).
inline void barrier() { asm volatile("" ::: "memory"); }

/// n cycles of FB_Blink through testing::cycles, one step() each.
inline std::uint32_t kit_cycles(std::uint64_t n) {
  FB_Blink fb;
  testing::cycles run{fb, cycle_time};
  for (std::uint64_t i = 0; i < n; ++i) {
    run.step();
    barrier();
  }
  return fb.nToggles.get().value();
}

/// The same cycles, written by hand.
inline std::uint32_t hand_cycles(std::uint64_t n) {
  FB_Blink fb;
  LTIME now{};
  for (std::uint64_t i = 0; i < n; ++i) {
    cycle_clock::set(now);
    fb();
    now = now + cycle_time;
    barrier();
  }
  return fb.nToggles.get().value();
}

/// n base cycles of the application through testing::plc, one step() each.
inline std::uint32_t kit_plc(std::uint64_t n) {
  testing::plc<make_blink<>> plc;
  for (std::uint64_t i = 0; i < n; ++i) {
    plc.step();
    barrier();
  }
  return plc.get<BLINK_PRG<0>>().fbBlink.nToggles.get().value();
}

/// The same cycles of the same application, without the kit.
inline std::uint32_t app_run_for(std::uint64_t n) {
  auto app = make_blink();
  app.start();
  for (std::uint64_t i = 0; i < n; ++i) {
    app.run_for(app.base_cycle());
    barrier();
  }
  const std::uint32_t toggles = app.get<BLINK_PRG<0>>().fbBlink.nToggles.get().value();
  app.stop();
  return toggles;
}

}  // namespace testing_programs
