// The CODESYS Util library's blocks beside the controllers (include/iecoop/util/, docs/util.md):
// each documented example, the cases the documentation leaves open as this implementation
// decides them, the time-dependent blocks at cycle times of 1, 10 and 7 ms with the values
// worked out from the formula in the comments, and property tests over random inputs.
#include "iecoop_test.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <random>
#include <vector>

#include "standard_blocks_test.hpp"

using namespace iecoop;
using iecoop_test::at_ms;

namespace {

// A fixed seed: every run draws the same inputs.
std::mt19937& random_engine() {
  static std::mt19937 engine{20261207U};
  return engine;
}
int random_int(int low, int high) { return std::uniform_int_distribution<int>{low, high}(random_engine()); }

}  // namespace

TEST_SUITE("util: bit and BCD functions") {
  TEST_CASE("EXTRACT, PACK, PUTBIT: the documented examples; a bit beyond the DWORD") {
    CHECK(EXTRACT(81, 4) == TRUE);  // 81 = 2#1010001
    CHECK(EXTRACT(33, 0) == TRUE);  // 33 = 2#100001
    CHECK(EXTRACT(33, 1) == FALSE);
    CHECK(EXTRACT(DWORD(0x80000000U), 31) == TRUE);
    CHECK(EXTRACT(DWORD(0xFFFFFFFFU), 32) == FALSE);  // left open: no such bit
    CHECK(PUTBIT(38, 4, TRUE) == DWORD(54));          // 2#100110 -> 2#110110
    CHECK(PUTBIT(38, 1, FALSE) == DWORD(36));         // 2#100110 -> 2#100100
    CHECK(PUTBIT(38, 40, TRUE) == DWORD(38));         // left open: unchanged
    CHECK(PACK(TRUE, FALSE, FALSE, FALSE, FALSE, FALSE, FALSE, TRUE) == BYTE(0x81));
  }

  TEST_CASE("UNPACK and PACK are inverse for every byte") {
    UNPACK bits;
    for (unsigned b = 0; b < 256; ++b) {
      bits("B"_ = BYTE(static_cast<std::uint8_t>(b)));
      REQUIRE(PACK(bits.B0, bits.B1, bits.B2, bits.B3, bits.B4, bits.B5, bits.B6, bits.B7) ==
              BYTE(static_cast<std::uint8_t>(b)));
      REQUIRE(bits.B3 == EXTRACT(DWORD(b), 3));
    }
  }

  TEST_CASE("BCD_TO_INT and INT_TO_BCD: the documented examples and the error values") {
    CHECK(BCD_TO_INT(73) == INT(49));   // 16#49
    CHECK(BCD_TO_INT(151) == INT(97));  // 16#97
    CHECK(BCD_TO_INT(15) == INT(-1));   // 16#0F: no BCD
    CHECK(BCD_TO_INT(BYTE(0xA0)) == INT(-1));
    CHECK(INT_TO_BCD(49) == BYTE(73));
    CHECK(INT_TO_BCD(97) == BYTE(151));
    CHECK(INT_TO_BCD(100) == BYTE(255));  // out of 0..99
    CHECK(INT_TO_BCD(-1) == BYTE(255));
  }

  TEST_CASE("BCD round trips: every INT 0..99, every byte") {
    for (int i = 0; i <= 99; ++i)
      REQUIRE(BCD_TO_INT(INT_TO_BCD(INT(static_cast<std::int16_t>(i)))) == INT(static_cast<std::int16_t>(i)));
    for (unsigned b = 0; b < 256; ++b) {
      const INT value = BCD_TO_INT(BYTE(static_cast<std::uint8_t>(b)));
      const bool bcd = (b >> 4U) <= 9U && (b & 0x0FU) <= 9U;
      REQUIRE((value == INT(-1)) == !bcd);
      if (bcd) REQUIRE(INT_TO_BCD(value) == BYTE(static_cast<std::uint8_t>(b)));
    }
    for (int n = 0; n < 2000; ++n) {
      const int i = random_int(-32768, 32767);
      const BYTE bcd = INT_TO_BCD(INT(static_cast<std::int16_t>(i)));
      REQUIRE((bcd == BYTE(255)) == (i < 0 || i > 99));
    }
  }
}

TEST_SUITE("util: analog monitors") {
  TEST_CASE("HYSTERESIS: TRUE below LOW, FALSE above HIGH, held in between; FALSE at first") {
    HYSTERESIS h;
    const auto call = [&h](int in) {
      h("IN"_ = INT(static_cast<std::int16_t>(in)), "HIGH"_ = INT(220), "LOW"_ = INT(200));
      return static_cast<bool>(h.OUT);
    };
    CHECK_FALSE(call(210));  // in the band at first: FALSE
    CHECK(call(199));        // below LOW
    CHECK(call(200));        // LOW itself: held
    CHECK(call(220));        // HIGH itself: held
    CHECK_FALSE(call(221));  // above HIGH
    CHECK_FALSE(call(205));  // held
  }

  TEST_CASE("HYSTERESIS never switches inside its band (random inputs and limits)") {
    HYSTERESIS h;
    for (int n = 0; n < 20000; ++n) {
      const int low = random_int(-1000, 1000);
      const int high = low + random_int(0, 500);
      const int in = random_int(-1600, 1600);
      const bool before = h.OUT;
      h("IN"_ = INT(static_cast<std::int16_t>(in)), "HIGH"_ = INT(static_cast<std::int16_t>(high)),
        "LOW"_ = INT(static_cast<std::int16_t>(low)));
      if (in >= low && in <= high) REQUIRE(static_cast<bool>(h.OUT) == before);
      if (in < low) REQUIRE(h.OUT == TRUE);
      if (in > high) REQUIRE(h.OUT == FALSE);
    }
  }

  TEST_CASE("LIMITALARM: O above HIGH, U below LOW, IL between; the limits themselves are inside") {
    LIMITALARM a;
    a("IN"_ = INT(901), "HIGH"_ = INT(900), "LOW"_ = INT(100));
    CHECK((a.O == TRUE && a.U == FALSE && a.IL == FALSE));
    a("IN"_ = INT(900));
    CHECK((a.O == FALSE && a.U == FALSE && a.IL == TRUE));
    a("IN"_ = INT(100));
    CHECK((a.O == FALSE && a.U == FALSE && a.IL == TRUE));
    a("IN"_ = INT(99));
    CHECK((a.O == FALSE && a.U == TRUE && a.IL == FALSE));
    // LOW > HIGH (left open): a value above HIGH and below LOW is O alone.
    a("IN"_ = INT(50), "HIGH"_ = INT(10), "LOW"_ = INT(100));
    CHECK((a.O == TRUE && a.U == FALSE && a.IL == FALSE));
  }

  TEST_CASE("LIMITALARM's O and U are never both TRUE, and IL is neither (random inputs and limits)") {
    LIMITALARM a;
    for (int n = 0; n < 20000; ++n) {
      a("IN"_ = INT(static_cast<std::int16_t>(random_int(-2000, 2000))),
        "HIGH"_ = INT(static_cast<std::int16_t>(random_int(-1000, 1000))),
        "LOW"_ = INT(static_cast<std::int16_t>(random_int(-1000, 1000))));
      REQUIRE_FALSE((a.O && a.U));
      REQUIRE(a.IL == BOOL(!a.O && !a.U));
    }
  }
}

TEST_SUITE("util: function manipulators") {
  // The documentation's example curve: (0,0) (250,50) (500,150) (750,400) and 7 x (1000,1000).
  ARRAY<POINT, 0, 10> example_curve() {
    ARRAY<POINT, 0, 10> kl;
    const int xs[] = {0, 250, 500, 750, 1000};
    const int ys[] = {0, 50, 150, 400, 1000};
    for (int i = 0; i <= 10; ++i) {
      const int k = i < 5 ? i : 4;
      kl[i].X = INT(static_cast<std::int16_t>(xs[k]));
      kl[i].Y = INT(static_cast<std::int16_t>(ys[k]));
    }
    return kl;
  }

  TEST_CASE("CHARCURVE: linear between the points, in integer arithmetic; the error codes") {
    ARRAY<POINT, 0, 10> kl = example_curve();
    CHARCURVE curve;
    const auto call = [&](int in, int n) {
      curve("IN"_ = INT(static_cast<std::int16_t>(in)), "N"_ = BYTE(static_cast<std::uint8_t>(n)), "P"_ = kl);
    };
    call(100, 5);
    CHECK(curve.OUT == INT(20));  // 0 + 100 * 50 / 250
    CHECK(curve.ERR == BYTE(0));
    call(333, 5);
    CHECK(curve.OUT == INT(83));  // 50 + 83 * 100 / 250 = 50 + 33.2: truncated
    call(600, 5);
    CHECK(curve.OUT == INT(250));  // 150 + 100 * 250 / 250
    call(1000, 5);
    CHECK(curve.OUT == INT(1000));
    CHECK(curve.ERR == BYTE(0));
    call(1010, 5);  // above the last X: ERR 2, the last Y
    CHECK(curve.ERR == BYTE(2));
    CHECK(curve.OUT == INT(1000));
    call(-5, 5);  // below the first X: ERR 2, the first Y
    CHECK(curve.ERR == BYTE(2));
    CHECK(curve.OUT == INT(0));
    call(300, 1);  // N outside 2..11: ERR 4, OUT kept
    CHECK(curve.ERR == BYTE(4));
    CHECK(curve.OUT == INT(0));
    call(300, 12);
    CHECK(curve.ERR == BYTE(4));
    // A point out of order is found on the way to IN's segment (completely at the largest X).
    kl[2].X = INT(100);
    call(200, 5);
    CHECK(curve.ERR == BYTE(0));  // (0..250) comes before the wrong point
    CHECK(curve.OUT == INT(40));
    call(1000, 5);
    CHECK(curve.ERR == BYTE(1));
    CHECK(curve.OUT == INT(40));  // kept
  }

  TEST_CASE("CHARCURVE: two points of one X are a step") {
    ARRAY<POINT, 0, 10> kl;
    kl[0] = POINT{INT(0), INT(0)};
    kl[1] = POINT{INT(10), INT(5)};
    kl[2] = POINT{INT(10), INT(50)};
    kl[3] = POINT{INT(20), INT(60)};
    CHARCURVE curve;
    curve("IN"_ = INT(10), "N"_ = BYTE(4), "P"_ = kl);
    CHECK(curve.OUT == INT(5));
    curve("IN"_ = INT(11), "N"_ = BYTE(4), "P"_ = kl);
    CHECK(curve.OUT == INT(51));
    CHECK(curve.ERR == BYTE(0));
  }

  TEST_CASE("CHARCURVE: the whole INT range in one segment (the product exceeds a DINT)") {
    ARRAY<POINT, 0, 10> kl;
    kl[0] = POINT{INT(-32768), INT(-32768)};
    kl[1] = POINT{INT(32767), INT(32767)};
    CHARCURVE curve;
    for (const int in : {-32768, -1, 0, 1, 12345, 32767}) {
      curve("IN"_ = INT(static_cast<std::int16_t>(in)), "N"_ = BYTE(2), "P"_ = kl);
      CHECK(curve.OUT == INT(static_cast<std::int16_t>(in)));  // -32768 + (IN + 32768) * 65535 / 65535
      CHECK(curve.ERR == BYTE(0));
    }
  }

  TEST_CASE("RAMP_REAL: per TIMEBASE of the cycle clock, at 1, 10 and 7 ms") {
    // ASCEND 1000 and DESCEND 500 per T#1s: 1.0 and 0.5 per ms, so a call c ms after the last
    // moves OUT by c up or c / 2 down (exact in REAL). The first call only takes the time.
    for (const int cycle : {1, 10, 7}) {
      CAPTURE(cycle);
      RAMP_REAL ramp;
      std::uint64_t t = 0;
      const auto call = [&](float in) {
        at_ms(t);
        ramp("IN"_ = REAL(in), "ASCEND"_ = REAL(1000.0F), "DESCEND"_ = REAL(500.0F), "TIMEBASE"_ = "T#1s"_iec);
        t += static_cast<std::uint64_t>(cycle);
      };
      call(100.0F);
      CHECK(ramp.OUT == REAL(0.0F));
      for (int k = 1; k * cycle < 100; ++k) {
        call(100.0F);
        REQUIRE(ramp.OUT == REAL(static_cast<float>(k * cycle)));
      }
      call(100.0F);  // the step would pass IN: OUT is IN
      CHECK(ramp.OUT == REAL(100.0F));
      call(0.0F);
      CHECK(ramp.OUT == REAL(100.0F - static_cast<float>(cycle) / 2.0F));
    }
  }

  TEST_CASE("RAMP_REAL: TIMEBASE T#0s is per call; RESET holds OUT and the ramp goes on from there") {
    RAMP_REAL ramp;
    at_ms(0);
    ramp("IN"_ = REAL(10.0F), "ASCEND"_ = REAL(4.0F), "DESCEND"_ = REAL(3.0F));
    CHECK(ramp.OUT == REAL(4.0F));  // per call: the first call moves already
    ramp();
    CHECK(ramp.OUT == REAL(8.0F));
    ramp("RESET"_ = TRUE);
    ramp("RESET"_ = TRUE);
    CHECK(ramp.OUT == REAL(8.0F));
    ramp("RESET"_ = FALSE, "IN"_ = REAL(-1.0F));
    CHECK(ramp.OUT == REAL(5.0F));
  }

  TEST_CASE("RAMP_INT: the fraction of an increment is kept, at 1, 10 and 7 ms") {
    // ASCEND 3 per T#10ms: after k calls c ms apart OUT is exactly floor(3 k c / 10).
    for (const int cycle : {1, 10, 7}) {
      CAPTURE(cycle);
      RAMP_INT ramp;
      at_ms(0);
      ramp("IN"_ = INT(500), "ASCEND"_ = INT(3), "DESCEND"_ = INT(2), "TIMEBASE"_ = "T#10ms"_iec);
      CHECK(ramp.OUT == INT(0));
      int k = 0;
      while (ramp.OUT < INT(500)) {
        ++k;
        at_ms(static_cast<std::uint64_t>(k * cycle));
        ramp();
        REQUIRE(ramp.OUT.get().value() == std::min(500, 3 * k * cycle / 10));
      }
      // Down at 2 per 10 ms from 500, the stretch starting afresh.
      const int top = k;
      while (ramp.OUT > INT(400)) {
        ++k;
        at_ms(static_cast<std::uint64_t>(k * cycle));
        ramp("IN"_ = INT(400));
        REQUIRE(ramp.OUT.get().value() == std::max(400, 500 - 2 * (k - top) * cycle / 10));
      }
    }
  }

  TEST_CASE("RAMP_INT and RAMP_REAL never step further than the slope allows (random inputs)") {
    for (const int cycle : {1, 10, 7}) {
      CAPTURE(cycle);
      RAMP_INT ramp_int;
      RAMP_REAL ramp_real;
      std::uint64_t t = 0;
      int ascend = random_int(1, 50);
      int descend = random_int(1, 50);
      int in = 0;
      // The stretch in one direction under way: the call before it began and OUT then.
      std::uint64_t stretch_start = 0;
      int stretch_out = 0;
      int direction = 0;
      for (int n = 0; n < 5000; ++n) {
        if (random_int(0, 40) == 0) in = random_int(-20000, 20000);
        const int before_int = ramp_int.OUT.get().value();
        const float before_real = ramp_real.OUT.get();
        const int desired = in > before_int ? 1 : in < before_int ? -1 : 0;
        if (desired != direction) {
          direction = desired;
          stretch_start = t >= static_cast<std::uint64_t>(cycle) ? t - static_cast<std::uint64_t>(cycle) : t;
          stretch_out = before_int;
        }
        at_ms(t);
        ramp_int("IN"_ = INT(static_cast<std::int16_t>(in)), "ASCEND"_ = INT(static_cast<std::int16_t>(ascend)),
                 "DESCEND"_ = INT(static_cast<std::int16_t>(descend)), "TIMEBASE"_ = "T#100ms"_iec);
        ramp_real("IN"_ = REAL(static_cast<float>(in)), "ASCEND"_ = REAL(static_cast<float>(ascend)),
                  "DESCEND"_ = REAL(static_cast<float>(descend)), "TIMEBASE"_ = "T#100ms"_iec);
        const int after_int = ramp_int.OUT.get().value();
        const float after_real = ramp_real.OUT.get();
        // REAL: each call at most rate x c / 100 (and never past IN), up to REAL's rounding.
        const double allowed = (after_real >= before_real ? ascend : descend) * cycle / 100.0;
        REQUIRE(std::abs(static_cast<double>(after_real) - before_real) <=
                allowed * (1 + 1e-6) + 4e-7 * std::abs(before_real) + 1e-6);
        // INT: over the stretch in one direction, at most rate x time / 100 (never a fraction more).
        if (direction != 0) {
          const int rate = direction > 0 ? ascend : descend;
          REQUIRE(std::abs(after_int - stretch_out) <= rate * static_cast<int>(t - stretch_start) / 100);
        }
        if (after_int == in) direction = 0;  // IN reached: the next move is a new stretch
        t += static_cast<std::uint64_t>(cycle);
      }
    }
  }
}

TEST_SUITE("util: signals") {
  // The calls at which OUT changed, in ms, over `until` ms of calls every `cycle` ms.
  std::vector<int> blink_changes(int cycle, int until) {
    BLINK blink;
    std::vector<int> changes;
    bool last = false;
    for (int t = 0; t <= until; t += cycle) {
      at_ms(static_cast<std::uint64_t>(t));
      blink("ENABLE"_ = TRUE, "TIMELOW"_ = "T#50ms"_iec, "TIMEHIGH"_ = "T#20ms"_iec);
      if (static_cast<bool>(blink.OUT) != last) changes.push_back(t);
      last = blink.OUT;
    }
    return changes;
  }

  TEST_CASE("BLINK: FALSE for TIMELOW, TRUE for TIMEHIGH, each phase from the call that began it") {
    // A phase ends on the first call at least its time after the call that began it.
    CHECK(blink_changes(1, 200) == std::vector<int>{50, 70, 120, 140, 190});
    CHECK(blink_changes(10, 200) == std::vector<int>{50, 70, 120, 140, 190});
    // 7 ms: TRUE at 56 (>= 50), FALSE at 77 (>= 56 + 20), TRUE at 133 (>= 127), FALSE at 154 (>= 153).
    CHECK(blink_changes(7, 200) == std::vector<int>{56, 77, 133, 154});
  }

  TEST_CASE("BLINK: OUT keeps its value while ENABLE is FALSE; enabling starts with FALSE") {
    BLINK blink;
    at_ms(0);
    blink("ENABLE"_ = TRUE, "TIMELOW"_ = "T#10ms"_iec, "TIMEHIGH"_ = "T#10ms"_iec);
    at_ms(10);
    blink();
    CHECK(blink.OUT == TRUE);
    at_ms(30);
    blink("ENABLE"_ = FALSE);
    CHECK(blink.OUT == TRUE);  // kept
    at_ms(40);
    blink("ENABLE"_ = TRUE);
    CHECK(blink.OUT == FALSE);  // the low phase first
    at_ms(49);
    blink();
    CHECK(blink.OUT == FALSE);
    at_ms(50);
    blink();
    CHECK(blink.OUT == TRUE);
  }

  TEST_CASE("GEN: each waveform at its documented points, time based at 1, 10 and 7 ms") {
    // PERIOD T#100ms, AMPLITUDE 100; t the time since the first call, p = t MOD 100.
    const auto expected = [](GEN_MODE mode, int p) {
      switch (mode) {
        case GEN_MODE::TRIANGLE: return p < 50 ? -100 + 4 * 100 * p / 100 : 300 - 4 * 100 * p / 100;
        case GEN_MODE::TRIANGLE_POS: return p < 50 ? 2 * 100 * p / 100 : 200 - 2 * 100 * p / 100;
        case GEN_MODE::SAWTOOTH_RISE: return -100 + 2 * 100 * p / 100;
        case GEN_MODE::SAWTOOTH_FALL: return 100 - 2 * 100 * p / 100;
        case GEN_MODE::RECTANGLE: return p < 50 ? -100 : 100;
        default: return 0;
      }
    };
    for (const GEN_MODE mode : {GEN_MODE::TRIANGLE, GEN_MODE::TRIANGLE_POS, GEN_MODE::SAWTOOTH_RISE,
                                GEN_MODE::SAWTOOTH_FALL, GEN_MODE::RECTANGLE}) {
      for (const int cycle : {1, 10, 7}) {
        CAPTURE(cycle);
        GEN gen;
        for (int t = 0; t < 300; t += cycle) {
          at_ms(static_cast<std::uint64_t>(1000 + t));  // the period starts at the first call
          gen("MODE"_ = mode, "BASE"_ = TRUE, "PERIOD"_ = "T#100ms"_iec, "AMPLITUDE"_ = INT(100));
          REQUIRE(gen.OUT.get().value() == expected(mode, t % 100));
        }
      }
    }
    // A few points by hand, 7 ms: TRIANGLE at 49 ms is -100 + 196 = 96, at 56 ms 300 - 224 = 76.
    GEN gen;
    std::vector<int> outs;
    for (int t = 0; t <= 56; t += 7) {
      at_ms(static_cast<std::uint64_t>(t));
      gen("MODE"_ = GEN_MODE::TRIANGLE, "BASE"_ = TRUE, "PERIOD"_ = "T#100ms"_iec, "AMPLITUDE"_ = INT(100));
      outs.push_back(gen.OUT.get().value());
    }
    CHECK(outs == std::vector<int>{-100, -72, -44, -16, 12, 40, 68, 96, 76});
  }

  TEST_CASE("GEN: the period goes on past 49.7 days, where TIME's milliseconds wrap") {
    // A T#7ms period, called every 1,000,000 ms (16.7 min) for 58 days: each call's place in the
    // period is the time since the first call MOD 7, also once that time exceeds 2^32 ms.
    GEN gen;
    for (std::uint64_t k = 0; k <= 5000; ++k) {
      const std::uint64_t t = k * 1'000'000U;
      at_ms(1234 + t);
      gen("MODE"_ = GEN_MODE::SAWTOOTH_RISE, "BASE"_ = TRUE, "PERIOD"_ = "T#7ms"_iec, "AMPLITUDE"_ = INT(70));
      REQUIRE(gen.OUT.get().value() == -70 + static_cast<int>(2 * 70 * (t % 7) / 7));
    }
  }

  TEST_CASE("GEN: SINE and COSINE rounded to the nearest INT; per call with BASE FALSE; RESET") {
    GEN gen;
    std::vector<int> sine;
    for (int k = 0; k < 8; ++k) {
      gen("MODE"_ = GEN_MODE::SINE, "BASE"_ = FALSE, "CYCLES"_ = INT(8), "AMPLITUDE"_ = INT(100));
      sine.push_back(gen.OUT.get().value());
    }
    CHECK(sine == std::vector<int>{0, 71, 100, 71, 0, -71, -100, -71});  // 100 sin(2 pi k / 8)
    GEN cosine;
    std::vector<int> values;
    for (int k = 0; k < 4; ++k) {
      cosine("MODE"_ = GEN_MODE::COSINUS, "BASE"_ = FALSE, "CYCLES"_ = INT(4), "AMPLITUDE"_ = INT(50));
      values.push_back(cosine.OUT.get().value());
    }
    CHECK(values == std::vector<int>{50, 0, -50, 0});
    GEN saw;
    values.clear();
    for (int k = 0; k < 6; ++k) {
      saw("MODE"_ = GEN_MODE::SAWTOOTH_RISE, "BASE"_ = FALSE, "CYCLES"_ = INT(4), "AMPLITUDE"_ = INT(100),
          "RESET"_ = BOOL(k == 3));
      values.push_back(saw.OUT.get().value());
    }
    CHECK(values == std::vector<int>{-100, -50, 0, 0, -100, -50});  // RESET: 0, then the period anew
    saw("CYCLES"_ = INT(0), "RESET"_ = FALSE);
    CHECK(saw.OUT == INT(0));  // no period
    CHECK(GEN{}.PERIOD == "T#1s"_iec);
    CHECK(GEN{}.CYCLES == INT(1000));
  }

  TEST_CASE("FREQ_MEASURE: the mean over PERIODS periods, at 1, 10 and 7 ms") {
    for (const int cycle : {1, 10, 7}) {
      CAPTURE(cycle);
      // A rising edge every 4 cycles (IN TRUE for one call): a period of 4c ms.
      FREQ_MEASURE freq;
      const int period = 4 * cycle;
      int edges = 0;
      for (int t = 0; t < 40 * cycle; t += cycle) {
        at_ms(static_cast<std::uint64_t>(t));
        const bool in = (t / cycle) % 4 == 0;
        freq("IN"_ = BOOL(in), "PERIODS"_ = INT(3));
        if (in) ++edges;
        // Three periods need four edges.
        REQUIRE(freq.VALID == BOOL(edges >= 4));
        if (edges >= 4) REQUIRE(freq.OUT == REAL(static_cast<float>(3.0 * 1e9 / (3.0 * period * 1e6))));
      }
      // The signal stops: VALID falls once more than three periods passed since the last edge.
      const int last_edge = 36 * cycle;
      for (int t = 40 * cycle; t < last_edge + 4 * period; t += cycle) {
        at_ms(static_cast<std::uint64_t>(t));
        freq("IN"_ = FALSE);
        REQUIRE(freq.VALID == BOOL(t - last_edge <= 3 * period));
      }
    }
  }

  TEST_CASE("FREQ_MEASURE: uneven periods, a jump, PERIODS out of range, RESET") {
    FREQ_MEASURE freq;
    const auto edge_at = [&](int t) {
      at_ms(static_cast<std::uint64_t>(t));
      freq("IN"_ = TRUE, "PERIODS"_ = INT(2));
      at_ms(static_cast<std::uint64_t>(t + 1));
      freq("IN"_ = FALSE, "PERIODS"_ = INT(2));
    };
    edge_at(0);
    edge_at(20);
    CHECK(freq.VALID == FALSE);  // one period of two
    edge_at(50);
    CHECK(freq.VALID == TRUE);
    CHECK(freq.OUT == REAL(40.0F));  // 2 periods in 50 ms
    edge_at(200);                    // 150 ms > 3 x 25 ms: a jump
    CHECK(freq.VALID == FALSE);
    edge_at(230);
    CHECK(freq.VALID == TRUE);
    CHECK(freq.OUT == REAL(static_cast<float>(2.0 * 1e9 / 180e6)));
    freq("PERIODS"_ = INT(11));
    CHECK(freq.VALID == FALSE);
    CHECK(freq.OUT == REAL(0.0F));
    freq("RESET"_ = TRUE, "PERIODS"_ = INT(1));
    CHECK(freq.OUT == REAL(0.0F));
    CHECK(freq.VALID == FALSE);
  }
}

TEST_SUITE("util: mathematical functions") {
  TEST_CASE("DERIVATIVE: the four-point slope, exact for a straight line once it has four values") {
    DERIVATIVE der;
    der("IN"_ = REAL(0.0F), "TM"_ = DWORD(10), "RESET"_ = TRUE);
    CHECK(der.OUT == REAL(0.0F));
    // IN = 2 t (t in s), 10 ms apart: (3 (IN - X3) + X1 - X2) / (10 x 0.01).
    const float expected[] = {0.6F, 1.4F, 2.0F, 2.0F, 2.0F};  // (3 x 0.02) / 0.1, (0.12 + 0.02) / 0.1, 0.2 / 0.1
    for (int k = 1; k <= 5; ++k) {
      der("IN"_ = REAL(0.02F * static_cast<float>(k)), "RESET"_ = FALSE);
      CHECK(der.OUT.get().value() == doctest::Approx(expected[k - 1]).epsilon(1e-5));
    }
    const REAL before = der.OUT;
    der("IN"_ = REAL(100.0F), "TM"_ = DWORD(0));  // no time passed: nothing changes
    CHECK(der.OUT == before);
    der("IN"_ = REAL(0.12F), "TM"_ = DWORD(10));
    CHECK(der.OUT.get().value() == doctest::Approx(2.0F).epsilon(1e-5));
  }

  TEST_CASE("INTEGRAL: the sum of IN x TM in seconds; OVERFLOW blocks it until RESET") {
    INTEGRAL integral;
    for (int k = 1; k <= 100; ++k) {
      integral("IN"_ = REAL(3.0F), "TM"_ = DWORD(7));
      REQUIRE(integral.OUT.get().value() == doctest::Approx(0.021 * k).epsilon(1e-5));
    }
    integral("IN"_ = REAL(1e38F), "TM"_ = DWORD(2000));  // 2E38 > 1E38
    CHECK(integral.OVERFLOW == TRUE);
    const REAL held = integral.OUT;
    integral("IN"_ = REAL(1.0F), "TM"_ = DWORD(1000));
    CHECK(integral.OUT == held);  // blocked
    integral("RESET"_ = TRUE);
    CHECK(integral.OUT == REAL(0.0F));
    CHECK(integral.OVERFLOW == FALSE);
    integral("RESET"_ = FALSE, "IN"_ = REAL(2.0F), "TM"_ = DWORD(500));
    CHECK(integral.OUT == REAL(1.0F));
  }

  TEST_CASE("LIN_TRAFO: the documented example; ERROR out of range and for IN_MIN = IN_MAX") {
    LIN_TRAFO trafo;
    trafo("IN"_ = REAL(5.0F), "IN_MIN"_ = REAL(0.0F), "IN_MAX"_ = REAL(10.0F), "OUT_MIN"_ = REAL(-20.0F),
          "OUT_MAX"_ = REAL(40.0F));
    CHECK(trafo.OUT == REAL(10.0F));  // 5 V: 10 degrees
    CHECK(trafo.ERROR == FALSE);
    trafo("IN"_ = REAL(12.0F));
    CHECK(trafo.ERROR == TRUE);
    CHECK(trafo.OUT == REAL(52.0F));  // the line extended
    trafo("IN"_ = REAL(10.0F));
    CHECK(trafo.ERROR == FALSE);
    CHECK(trafo.OUT == REAL(40.0F));
    trafo("IN"_ = REAL(3.0F), "IN_MAX"_ = REAL(0.0F));
    CHECK(trafo.ERROR == TRUE);
    CHECK(trafo.OUT == REAL(40.0F));  // kept
  }

  TEST_CASE("STATISTICS_INT and STATISTICS_REAL: MN, MX, AVG since the last RESET") {
    STATISTICS_INT s;
    CHECK(s.MN == INT(32767));
    CHECK(s.MX == INT(-32768));
    for (const int v : {5, -3, 10}) s("IN"_ = INT(static_cast<std::int16_t>(v)));
    CHECK(s.MN == INT(-3));
    CHECK(s.MX == INT(10));
    CHECK(s.AVG == INT(4));
    s("IN"_ = INT(-14));
    CHECK(s.AVG == INT(-0));  // -2 / 4 truncates toward zero
    s("RESET"_ = TRUE, "IN"_ = INT(99));
    CHECK(s.AVG == INT(0));
    CHECK(s.MN == INT(32767));
    s("RESET"_ = FALSE, "IN"_ = INT(7));
    CHECK((s.MN == INT(7) && s.MX == INT(7) && s.AVG == INT(7)));

    STATISTICS_REAL r;
    CHECK(r.MN == REAL(3.402823466E+38F));
    CHECK(r.MX == REAL(-3.402823466E+38F));
    for (const float v : {1.5F, -2.0F, 6.5F}) r("IN"_ = REAL(v));
    CHECK(r.MN == REAL(-2.0F));
    CHECK(r.MX == REAL(6.5F));
    CHECK(r.AVG == REAL(2.0F));
  }

  TEST_CASE("VARIANCE: the population variance since the last RESET") {
    VARIANCE v;
    v("IN"_ = REAL(3.0F));
    CHECK(v.OUT == REAL(0.0F));  // one value
    v("RESET"_ = TRUE);
    for (const float x : {2.0F, 4.0F, 4.0F, 4.0F, 5.0F, 5.0F, 7.0F, 9.0F}) v("IN"_ = REAL(x), "RESET"_ = FALSE);
    CHECK(v.OUT == REAL(4.0F));
  }
}
