// TON, TOF, TP and their LTIME forms: each timing diagram as a table of calls, covering the
// edge cases of IEC 61131-3's timing diagrams as MatIEC's state machines implement them
// (docs/standard-library.md).
#include "iecoop_test.hpp"

#include <cstdint>
#include <initializer_list>
#include <limits>
#include <type_traits>

#include "standard_blocks_test.hpp"

using namespace iecoop;
using iecoop_test::at_ms;
using iecoop_test::ms;

namespace {

/// One call of a timer: the cycle's time stamp, the inputs, and the outputs expected after it.
struct timer_step {
  std::uint64_t time_ms;
  bool in;
  std::uint32_t pt_ms;
  bool q;
  std::uint32_t et_ms;
};

/// Runs the calls on one fresh timer and checks every output.
template <class Timer>
void check_timer(std::initializer_list<timer_step> steps) {
  Timer timer;
  int row = 0;
  for (const timer_step& step : steps) {
    ++row;
    at_ms(step.time_ms);
    timer("IN"_ = BOOL(step.in), "PT"_ = TIME::from_ticks(step.pt_ms));
    INFO("row ", row, " at ", step.time_ms, " ms");
    CHECK(timer.Q == BOOL(step.q));
    CHECK(timer.ET == TIME::from_ticks(step.et_ms));
  }
}

}  // namespace

// Outputs can be read but not written from outside, as in ST.
static_assert(!std::is_assignable_v<decltype((std::declval<TON&>().Q)), BOOL>);
static_assert(!std::is_assignable_v<decltype((std::declval<TP&>().ET)), TIME>);
static_assert(std::is_assignable_v<decltype((std::declval<TON&>().PT)), TIME>);

TEST_SUITE("standard blocks: TON") {
  TEST_CASE("the IEC timing diagram: ET not updated on the edge, Q at ET = PT, ET clamped") {
    check_timer<TON>({
        //  t    IN   PT    Q      ET
        {0, false, 100, false, 0},
        {10, true, 100, false, 0},  // rising edge: the timer starts, ET is not written yet
        {20, true, 100, false, 10},
        {109, true, 100, false, 99},
        {110, true, 100, true, 100},  // elapsed = PT exactly: Q rises (>=)
        {500, true, 100, true, 100},  // ET stays at PT
        {510, false, 100, false, 0},  // IN FALSE resets at once
        {520, true, 100, false, 0},   // a new edge starts again from 0
        {540, true, 100, false, 20},
    });
  }

  TEST_CASE("IN dropped exactly when PT is reached: no pulse on Q") {
    check_timer<TON>({
        {0, true, 50, false, 0},
        {49, true, 50, false, 49},
        {50, false, 50, false, 0},  // IN FALSE wins over the expiry in the same call
        {60, false, 50, false, 0},
    });
  }

  TEST_CASE("IN TRUE on the very first call counts as a rising edge") {
    check_timer<TON>({
        {1000, true, 30, false, 0},
        {1030, true, 30, true, 30},
    });
  }

  TEST_CASE("PT = 0: Q rises on the call after the edge, not on the edge itself") {
    check_timer<TON>({
        {0, true, 0, false, 0},
        {0, true, 0, true, 0},  // same cycle time, next call
        {5, false, 0, false, 0},
    });
  }

  TEST_CASE("PT changed while timing takes effect at the next call") {
    check_timer<TON>({
        {0, true, 100, false, 0},
        {40, true, 100, false, 40},
        {60, true, 200, false, 60},  // raised: goes on counting
        {150, true, 200, false, 150},
        {160, true, 120, true, 120},  // lowered below the elapsed time: expires now, ET = new PT
        {170, true, 120, true, 120},
    });
  }

  TEST_CASE("PT changed after expiry: ET stays at the PT of the expiry, Q stays TRUE") {
    check_timer<TON>({
        {0, true, 100, false, 0},
        {100, true, 100, true, 100},
        {110, true, 300, true, 100},  // raised: MatIEC keeps ET and Q
        {120, true, 50, true, 100},   // lowered: the same
        {130, false, 50, false, 0},
    });
  }

  TEST_CASE("a short FALSE restarts the timing") {
    check_timer<TON>({
        {0, true, 100, false, 0},
        {90, true, 100, false, 90},
        {95, false, 100, false, 0},
        {96, true, 100, false, 0},
        {190, true, 100, false, 94},
        {196, true, 100, true, 100},
    });
  }

  TEST_CASE("two calls in one cycle see the same time") {
    TON tmr;
    at_ms(0);
    tmr("IN"_ = TRUE, "PT"_ = ms(1000));
    at_ms(400);
    tmr();
    CHECK(tmr.ET == ms(400));
    tmr();  // the clock has not moved: neither has ET
    CHECK(tmr.ET == ms(400));
  }

  TEST_CASE("timing across the 49.7-day wrap of TIME's milliseconds") {
    // TIME counts milliseconds modulo 2^32; the elapsed time is a difference, so a timer
    // running while the millisecond count wraps measures correctly.
    constexpr std::uint64_t wrap = std::uint64_t{1} << 32;
    check_timer<TON>({
        {wrap - 30, true, 100, false, 0},
        {wrap - 1, true, 100, false, 29},
        {wrap + 20, true, 100, false, 50},
        {wrap + 70, true, 100, true, 100},
    });
  }

  TEST_CASE("named outputs are read with =>") {
    TON tmr;
    BOOL q;
    TIME et;
    at_ms(0);
    tmr("IN"_ = TRUE, "PT"_ = ms(20), "Q"_ >> q, "ET"_ >> et);
    at_ms(25);
    tmr("Q"_ >> q, "ET"_ >> et);
    CHECK(q == TRUE);
    CHECK(et == ms(20));
  }
}

TEST_SUITE("standard blocks: TOF") {
  TEST_CASE("the IEC timing diagram: Q held for PT after IN falls") {
    check_timer<TOF>({
        {0, false, 100, false, 0},  // IN FALSE on the first call: no falling edge
        {10, true, 100, true, 0},
        {50, false, 100, true, 0},  // falling edge: the timer starts, ET not written yet
        {80, false, 100, true, 30},
        {149, false, 100, true, 99},
        {150, false, 100, false, 100},  // elapsed = PT: Q falls, ET = PT
        {400, false, 100, false, 100},  // and stays
        {410, true, 100, true, 0},      // IN TRUE resets ET
    });
  }

  TEST_CASE("IN TRUE again while the delay runs: Q stays TRUE and the delay starts anew") {
    check_timer<TOF>({
        {0, true, 100, true, 0},
        {10, false, 100, true, 0},
        {60, false, 100, true, 50},
        {70, true, 100, true, 0},
        {80, false, 100, true, 0},
        {170, false, 100, true, 90},
        {180, false, 100, false, 100},
    });
  }

  TEST_CASE("IN TRUE exactly when the delay ends keeps Q TRUE") {
    check_timer<TOF>({
        {0, true, 40, true, 0},
        {10, false, 40, true, 0},
        {50, true, 40, true, 0},
        {60, false, 40, true, 0},
        {100, false, 40, false, 40},
    });
  }

  TEST_CASE("PT = 0: Q stays TRUE for the call of the falling edge only") {
    check_timer<TOF>({
        {0, true, 0, true, 0},
        {10, false, 0, true, 0},
        {10, false, 0, false, 0},
    });
  }

  TEST_CASE("PT lowered while the delay runs ends it at the next call, raised after it, nothing changes") {
    check_timer<TOF>({
        {0, true, 100, true, 0},
        {10, false, 100, true, 0},
        {70, false, 100, true, 60},
        {80, false, 50, false, 50},
        {90, false, 500, false, 50},
    });
  }
}

TEST_SUITE("standard blocks: TP") {
  TEST_CASE("the IEC timing diagram: a pulse of PT, ET held while IN stays TRUE") {
    check_timer<TP>({
        {0, false, 100, false, 0},
        {10, true, 100, true, 0},  // rising edge: pulse starts, ET not written yet
        {60, true, 100, true, 50},
        {110, true, 100, false, 100},  // the pulse is over; IN still TRUE: ET holds PT
        {300, true, 100, false, 100},
        {310, false, 100, false, 0},  // IN FALSE: ET back to 0
    });
  }

  TEST_CASE("the pulse ends while IN is already FALSE: ET goes to 0 in the same call") {
    check_timer<TP>({
        {0, true, 100, true, 0}, {20, false, 100, true, 20}, {100, false, 100, false, 0},  // ET = PT is never visible
    });
  }

  TEST_CASE("edges during the pulse are ignored: TP does not retrigger") {
    check_timer<TP>({
        {0, true, 100, true, 0},
        {30, false, 100, true, 30},
        {40, true, 100, true, 40},  // a new edge while the pulse runs
        {50, false, 100, true, 50},
        {60, true, 100, true, 60},
        {100, true, 100, false, 100},  // the pulse ends at 100 as started, not at 160
        {120, true, 100, false, 100},  // IN still TRUE: no new pulse
        {130, false, 100, false, 0},
        {140, true, 100, true, 0},  // the next edge starts the next pulse
    });
  }

  TEST_CASE("PT = 0: Q is TRUE for the call of the edge only") {
    check_timer<TP>({
        {0, true, 0, true, 0},
        {0, true, 0, false, 0},
        {5, false, 0, false, 0},
    });
  }

  TEST_CASE("PT lowered during the pulse ends it at the next call") {
    check_timer<TP>({
        {0, true, 100, true, 0},
        {60, true, 100, true, 60},
        {70, true, 40, false, 40},
        {80, true, 400, false, 40},  // raised after the pulse: ET stays at the PT it ended with
    });
  }
}

TEST_SUITE("standard blocks: LTON, LTOF, LTP") {
  TEST_CASE("LTIME timers measure nanoseconds of the cycle clock") {
    LTON on;
    LTOF off;
    LTP pulse;
    const LTIME pt = LTIME::from_ticks(1500);
    cycle_clock::set(LTIME::from_ticks(1'000'000'000'000));
    on("IN"_ = TRUE, "PT"_ = pt);
    off("IN"_ = TRUE, "PT"_ = pt);
    pulse("IN"_ = TRUE, "PT"_ = pt);
    cycle_clock::advance(LTIME::from_ticks(1499));
    on();
    off("IN"_ = FALSE);
    pulse();
    CHECK(on.Q == FALSE);
    CHECK(on.ET == LTIME::from_ticks(1499));
    CHECK(off.ET == LTIME());  // the falling edge's call
    CHECK(pulse.Q == TRUE);
    cycle_clock::advance(LTIME::from_ticks(1));
    on();
    off();
    pulse();
    CHECK(on.Q == TRUE);
    CHECK(on.ET == pt);
    CHECK(off.Q == TRUE);
    CHECK(off.ET == LTIME::from_ticks(1));
    CHECK(pulse.Q == FALSE);
    CHECK(pulse.ET == pt);
    cycle_clock::advance(LTIME::from_ticks(1499));
    off();
    CHECK(off.Q == FALSE);
    CHECK(off.ET == pt);
  }

  TEST_CASE("a TIME timer sees the cycle clock truncated to whole milliseconds") {
    TON tmr;
    cycle_clock::set(LTIME::from_ticks(1'999'999));  // 1.999999 ms: TIME 1 ms
    tmr("IN"_ = TRUE, "PT"_ = ms(2));
    cycle_clock::set(LTIME::from_ticks(3'000'000));  // 3 ms: 2 ms elapsed in TIME's terms
    tmr();
    CHECK(tmr.Q == TRUE);
  }
}

TEST_SUITE("cycle clock") {
  TEST_CASE("set, advance, and both widths") {
    cycle_clock::set(LTIME::from_ticks(5'000'000'123));
    CHECK(cycle_clock::now() == LTIME::from_ticks(5'000'000'123));
    CHECK(cycle_clock::now_as<TIME>() == ms(5000));
    cycle_clock::advance(std::chrono::milliseconds(250));
    CHECK(cycle_clock::now_as<TIME>() == ms(5250));
    CHECK(cycle_clock::now_as<LTIME>() == LTIME::from_ticks(5'250'000'123));
  }

  TEST_CASE("a scope gives the interrupted cycle its time stamp back") {
    at_ms(100);
    TON slow;
    slow("IN"_ = TRUE, "PT"_ = ms(1000));
    at_ms(300);
    {
      const cycle_clock::scope fast_cycle(LTIME(std::chrono::milliseconds(350)));
      CHECK(cycle_clock::now_as<TIME>() == ms(350));
    }
    slow();  // the slow task's cycle goes on at its own time stamp
    CHECK(slow.ET == ms(200));
  }
}
