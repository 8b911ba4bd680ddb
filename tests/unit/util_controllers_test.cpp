// The CODESYS Util library's controllers PD, PID and PID_FIXCYCLE (include/iecoop/util/
// controllers.hpp, docs/util.md, "Controllers"): the documented formula, call by call at cycle
// times of 1, 10 and 7 ms with the values worked out in the comments; RESET, MANUAL (bumpless),
// the limits and their anti-windup, OVERFLOW, TN = 0, the parameters taken only at the start,
// a RESET or in manual mode. The closed loop against an independent simulation is
// tests/util/pid_scipy.py.
#include "iecoop_test.hpp"

#include <cstdint>

#include "standard_blocks_test.hpp"

using namespace iecoop;
using iecoop_test::at_ms;

namespace {

float value(const REAL& r) { return r.value(); }

}  // namespace

TEST_SUITE("util: controllers") {
  TEST_CASE("PID: the first call is Y_OFFSET; then KP (e + integral / TN), at 1, 10 and 7 ms") {
    // e = 1 constant, KP 2, TN 4 s, TV 0: after k calls c ms apart the integral is k c / 1000
    // (summed in REAL) and Y = 2 (1 + k c / 4000) + 0.5.
    for (const int cycle : {1, 10, 7}) {
      CAPTURE(cycle);
      PID pid;
      at_ms(0);
      pid("ACTUAL"_ = REAL(2.0F), "SET_POINT"_ = REAL(3.0F), "KP"_ = REAL(2.0F), "TN"_ = REAL(4.0F),
          "Y_OFFSET"_ = REAL(0.5F));
      CHECK(pid.Y == REAL(0.5F));
      float integral = 0.0F;
      for (int k = 1; k <= 500; ++k) {
        at_ms(static_cast<std::uint64_t>(k * cycle));
        pid();
        integral = integral + 1.0F * (static_cast<float>(cycle) / 1000.0F);
        REQUIRE(value(pid.Y) == 2.0F * (1.0F + integral / 4.0F) + 0.5F);
        REQUIRE(value(pid.Y) == doctest::Approx(2.0 * (1.0 + k * cycle / 4000.0) + 0.5).epsilon(1e-5));
      }
      CHECK(pid.LIMITS_ACTIVE == FALSE);
      CHECK(pid.OVERFLOW == FALSE);
    }
  }

  TEST_CASE("PD: the derivative of a ramp, exact once four values are in; TV 0 is a P controller") {
    // ACTUAL rises 0.5 per second, SET_POINT 0: e = -0.5 t, de/dt = -0.5. KP 2, TV 3: from the
    // fourth call after the first, Y = 2 (e - 1.5).
    for (const int cycle : {1, 10, 7}) {
      CAPTURE(cycle);
      PD pd;
      for (int k = 0; k <= 50; ++k) {
        const double t = k * cycle / 1000.0;
        at_ms(static_cast<std::uint64_t>(k * cycle));
        pd("ACTUAL"_ = REAL(static_cast<float>(0.5 * t)), "SET_POINT"_ = REAL(0.0F), "KP"_ = REAL(2.0F),
           "TV"_ = REAL(3.0F));
        if (k >= 4) REQUIRE(value(pd.Y) == doctest::Approx(2.0 * (-0.5 * t - 1.5)).epsilon(1e-4));
      }
      PD p;
      at_ms(0);
      p("ACTUAL"_ = REAL(1.0F), "SET_POINT"_ = REAL(4.0F), "KP"_ = REAL(3.0F));
      at_ms(static_cast<std::uint64_t>(cycle));
      p();
      CHECK(p.Y == REAL(9.0F));  // KP x e
    }
  }

  TEST_CASE("PID: the limits, LIMITS_ACTIVE and the anti-windup") {
    // e = 1, KP 1, TN 1 s, 10 ms: Y = 1 + 0.01 k reaches Y_MAX 1.5 at k = 50; from there the
    // integral is held at what gives 1.5 (0.5), so that when e falls to 0 Y is 0.5 at once
    // instead of unwinding a growing integral.
    PID pid;
    at_ms(0);
    pid("ACTUAL"_ = REAL(0.0F), "SET_POINT"_ = REAL(1.0F), "KP"_ = REAL(1.0F), "TN"_ = REAL(1.0F),
        "Y_MIN"_ = REAL(-1.0F), "Y_MAX"_ = REAL(1.5F));
    int k = 0;
    while (pid.LIMITS_ACTIVE == FALSE && k < 100) {
      ++k;
      at_ms(static_cast<std::uint64_t>(10 * k));
      pid();
    }
    CHECK(k == doctest::Approx(50).epsilon(0.02));
    CHECK(pid.Y == REAL(1.5F));
    for (int n = 0; n < 200; ++n) {  // two seconds at the limit
      ++k;
      at_ms(static_cast<std::uint64_t>(10 * k));
      pid();
      REQUIRE(pid.Y == REAL(1.5F));
      REQUIRE(pid.LIMITS_ACTIVE == TRUE);
    }
    ++k;
    at_ms(static_cast<std::uint64_t>(10 * k));
    pid("ACTUAL"_ = REAL(1.0F));  // e = 0
    CHECK(value(pid.Y) == doctest::Approx(0.5).epsilon(1e-5));
    CHECK(pid.LIMITS_ACTIVE == FALSE);
    ++k;
    at_ms(static_cast<std::uint64_t>(10 * k));
    pid("ACTUAL"_ = REAL(5.0F));  // e = -4: -4 + 0.5 - 0.04 below Y_MIN
    CHECK(pid.Y == REAL(-1.0F));
    CHECK(pid.LIMITS_ACTIVE == TRUE);
    // Y_MIN = Y_MAX = 0: no limits.
    PID free;
    at_ms(0);
    free("ACTUAL"_ = REAL(0.0F), "SET_POINT"_ = REAL(100.0F), "KP"_ = REAL(1.0F));
    at_ms(10);
    free();
    CHECK(free.Y == REAL(100.0F));
    CHECK(free.LIMITS_ACTIVE == FALSE);
  }

  TEST_CASE("PID: RESET and MANUAL; the switch back to automatic is bumpless") {
    PID pid;
    at_ms(0);
    pid("ACTUAL"_ = REAL(0.0F), "SET_POINT"_ = REAL(1.0F), "KP"_ = REAL(2.0F), "TN"_ = REAL(1.0F),
        "Y_OFFSET"_ = REAL(1.0F));
    for (int k = 1; k <= 10; ++k) {
      at_ms(static_cast<std::uint64_t>(10 * k));
      pid();
    }
    CHECK(value(pid.Y) == doctest::Approx(2.0 * 1.1 + 1.0).epsilon(1e-5));
    at_ms(110);
    pid("RESET"_ = TRUE);
    CHECK(pid.Y == REAL(1.0F));  // Y_OFFSET
    at_ms(120);
    pid("RESET"_ = FALSE, "MANUAL"_ = TRUE, "Y_MANUAL"_ = REAL(7.0F));
    CHECK(pid.Y == REAL(7.0F));
    at_ms(130);
    pid();
    CHECK(pid.Y == REAL(7.0F));
    // Back in automatic with the same e: Y goes on from Y_MANUAL by one step of the integral
    // (KP e dt / TN = 2 x 1 x 0.01 / 1).
    at_ms(140);
    pid("MANUAL"_ = FALSE);
    CHECK(value(pid.Y) == doctest::Approx(7.02).epsilon(1e-5));
  }

  TEST_CASE("PID: KP, TN and TV are taken at the start, a RESET and in manual mode only") {
    PID pid;
    at_ms(0);
    pid("ACTUAL"_ = REAL(0.0F), "SET_POINT"_ = REAL(1.0F), "KP"_ = REAL(1.0F));
    at_ms(10);
    pid("KP"_ = REAL(5.0F));  // in automatic: not taken
    CHECK(pid.Y == REAL(1.0F));
    at_ms(20);
    pid("RESET"_ = TRUE);
    at_ms(30);
    pid("RESET"_ = FALSE);
    CHECK(pid.Y == REAL(5.0F));
    at_ms(40);
    pid("KP"_ = REAL(3.0F), "MANUAL"_ = TRUE);
    at_ms(50);
    pid("MANUAL"_ = FALSE);
    CHECK(pid.Y == REAL(3.0F));  // TN 0: no integral, so no bumpless transfer either
  }

  TEST_CASE("PID: TN 0 switches the integral off; two calls in one millisecond change nothing") {
    PID pid;
    at_ms(0);
    pid("ACTUAL"_ = REAL(0.0F), "SET_POINT"_ = REAL(2.0F), "KP"_ = REAL(1.5F), "TN"_ = REAL(0.0F));
    for (int k = 1; k <= 20; ++k) {
      at_ms(static_cast<std::uint64_t>(7 * k));
      pid();
      REQUIRE(pid.Y == REAL(3.0F));
    }
    pid("SET_POINT"_ = REAL(4.0F));  // same millisecond: dt = 0
    CHECK(pid.Y == REAL(3.0F));
  }

  TEST_CASE("PID: OVERFLOW suspends the controller until RESET") {
    PID pid;
    at_ms(0);
    pid("ACTUAL"_ = REAL(0.0F), "SET_POINT"_ = REAL(2e38F), "KP"_ = REAL(1e-38F), "TN"_ = REAL(1.0F));
    at_ms(1000);
    pid();  // the integral would be 2E38
    CHECK(pid.OVERFLOW == TRUE);
    const REAL held = pid.Y;
    at_ms(2000);
    pid("SET_POINT"_ = REAL(1.0F));
    CHECK(pid.Y == held);
    CHECK(pid.OVERFLOW == TRUE);
    at_ms(3000);
    pid("RESET"_ = TRUE);
    CHECK(pid.OVERFLOW == FALSE);
  }

  TEST_CASE("PID_FIXCYCLE with CYCLE 0.01 is PID called every 10 ms; CYCLE 0 changes nothing") {
    PID pid;
    PID_FIXCYCLE fix;
    for (int k = 0; k < 300; ++k) {
      at_ms(static_cast<std::uint64_t>(10 * k));
      const REAL actual = REAL(static_cast<float>(k % 37) * 0.25F);
      const BOOL manual = BOOL(k >= 100 && k < 120);
      pid("ACTUAL"_ = actual, "SET_POINT"_ = REAL(4.0F), "KP"_ = REAL(1.2F), "TN"_ = REAL(0.8F), "TV"_ = REAL(0.05F),
          "Y_MIN"_ = REAL(-10.0F), "Y_MAX"_ = REAL(10.0F), "MANUAL"_ = manual, "Y_MANUAL"_ = REAL(2.0F));
      fix("ACTUAL"_ = actual, "SET_POINT"_ = REAL(4.0F), "KP"_ = REAL(1.2F), "TN"_ = REAL(0.8F), "TV"_ = REAL(0.05F),
          "Y_MIN"_ = REAL(-10.0F), "Y_MAX"_ = REAL(10.0F), "MANUAL"_ = manual, "Y_MANUAL"_ = REAL(2.0F),
          "CYCLE"_ = REAL(0.01F));
      REQUIRE(pid.Y == fix.Y);
      REQUIRE(pid.LIMITS_ACTIVE == fix.LIMITS_ACTIVE);
    }
    const REAL before = fix.Y;
    fix("CYCLE"_ = REAL(0.0F), "SET_POINT"_ = REAL(100.0F));
    CHECK(fix.Y == before);
  }
}
