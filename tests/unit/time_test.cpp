// TIME and LTIME: CODESYS representation, std::chrono interoperability, wrap-around
// arithmetic, and the fault path for division by zero.
#include "iecoop_test.hpp"

#include <chrono>
#include <cstdint>
#include <limits>
#include <type_traits>

using namespace iecoop;
using namespace std::chrono_literals;
using iecoop_test::fault_recorder;
using iecoop_test::opaque;

// TIME: unsigned 32-bit milliseconds; LTIME: unsigned 64-bit nanoseconds (CDS-TIME).
static_assert(sizeof(TIME) == 4 && std::is_same_v<TIME::rep, std::uint32_t> &&
              std::is_same_v<TIME::period, std::milli>);
static_assert(sizeof(LTIME) == 8 && std::is_same_v<LTIME::rep, std::uint64_t> &&
              std::is_same_v<LTIME::period, std::nano>);
static_assert(std::is_trivially_copyable_v<TIME> && std::is_trivially_copyable_v<LTIME>);
static_assert(TIME::max().count() == 4294967295u);  // T#49d17h2m47s295ms
static_assert(LTIME::max().count() == 18446744073709551615u);

// std::chrono in: implicit where no precision is lost.
static_assert(std::is_convertible_v<std::chrono::milliseconds, TIME> &&
              std::is_convertible_v<std::chrono::hours, TIME>);
static_assert(!std::is_convertible_v<std::chrono::microseconds, TIME> &&
              !std::is_constructible_v<TIME, std::chrono::microseconds>);
static_assert(std::is_convertible_v<std::chrono::nanoseconds, LTIME>);
static_assert(!std::is_constructible_v<TIME, std::chrono::duration<double>>);
// std::chrono out: implicit to durations at least as fine.
static_assert(std::is_convertible_v<TIME, std::chrono::milliseconds> &&
              std::is_convertible_v<TIME, std::chrono::nanoseconds>);
static_assert(!std::is_convertible_v<TIME, std::chrono::seconds>);
static_assert(std::is_convertible_v<TIME, std::chrono::duration<double>>);
static_assert(std::is_convertible_v<LTIME, std::chrono::nanoseconds> &&
              !std::is_convertible_v<LTIME, std::chrono::microseconds>);
// TIME widens to LTIME implicitly; LTIME narrows to TIME only explicitly.
static_assert(std::is_convertible_v<TIME, LTIME> && !std::is_convertible_v<LTIME, TIME> &&
              std::is_constructible_v<TIME, LTIME>);
// An integer constant counts milliseconds (PT := 300 in CODESYS); other types do not convert.
static_assert(TIME(300).count() == 300);
static_assert(!std::is_convertible_v<DINT, TIME> && !std::is_convertible_v<REAL, TIME>);

TEST_SUITE("TIME and LTIME") {
  TEST_CASE("TIME starts at T#0ms and counts milliseconds") {
    TIME t;
    CHECK(t.count() == 0u);
    t = 1500ms;
    CHECK(t.count() == 1500u);
    t = 2min;
    CHECK(t.count() == 120000u);
    CHECK(t == 120s);
    const TIME p = 300;
    CHECK(p == 300ms);
  }

  TEST_CASE("LTIME counts nanoseconds") {
    LTIME t = 1500us;
    CHECK(t.count() == 1500000u);
    t = 3ns;
    CHECK(t.count() == 3u);
    t = 25h;
    CHECK(t.count() == 90000000000000u);
  }

  TEST_CASE("TIME converts back to std::chrono") {
    const TIME t = 1500ms;
    const std::chrono::milliseconds ms = t;
    const std::chrono::nanoseconds ns = t;
    const std::chrono::duration<double> seconds = t;
    CHECK(ms.count() == 1500);
    CHECK(ns.count() == 1500000000);
    CHECK(seconds.count() == doctest::Approx(1.5));
    CHECK(t.chrono() == std::chrono::duration<std::uint32_t, std::milli>(1500));
    CHECK(std::chrono::duration_cast<std::chrono::seconds>(std::chrono::milliseconds(t)).count() == 1);
  }

  TEST_CASE("TIME and LTIME convert into each other") {
    const TIME t = 1500ms;
    const LTIME l = t;
    CHECK(l.count() == 1500000000u);
    const LTIME fine = 1999999us;
    CHECK(static_cast<TIME>(fine) == 1999ms);        // truncated to whole milliseconds
    const LTIME huge = std::chrono::hours(24 * 60);  // 60 days: beyond TIME's 49.7 days
    CHECK(static_cast<TIME>(huge).count() == static_cast<std::uint32_t>(5184000000u % 4294967296u));
  }

  TEST_CASE("addition and subtraction wrap modulo 2^32 ms like CODESYS's TIME") {
    const TIME zero;
    CHECK(opaque(zero) - opaque(TIME(1)) == TIME::max());
    CHECK(opaque(TIME::max()) + opaque(TIME(1)) == zero);
    TIME t = 1s;
    t += 500ms;
    t -= 250ms;
    CHECK(t == 1250ms);
    const LTIME lzero;
    CHECK(opaque(lzero) - opaque(LTIME(1ns)) == LTIME::max());
  }

  TEST_CASE("multiplication and division by numbers (ST's MUL and DIV on TIME)") {
    const TIME t = 1500ms;
    CHECK(t * 2 == 3s);
    CHECK(2 * t == 3s);
    CHECK(t * INT(3) == 4500ms);
    CHECK(t * 1.5 == 2250ms);
    CHECK(t * REAL(0.001f) == 2ms);  // 1.5 ms rounds to 2 ms (halves away from zero)
    CHECK(t / 4 == 375ms);
    CHECK(t / UDINT(1000) == 1ms);
    CHECK(t / 2.0 == 750ms);
    CHECK(TIME(7) / 2 == 3ms);  // truncates like integer division
    TIME u = 100ms;
    u *= 3;
    u /= 4;
    CHECK(u == 75ms);
    CHECK(opaque(TIME::max()) * 2 == TIME::max() - TIME(1));  // wraps
    CHECK(TIME(10) * -1 == TIME::max() - TIME(9));            // a negative product wraps too
  }

  TEST_CASE("division of a duration by zero reports a fault and yields T#0ms") {
    fault_recorder faults;
    CHECK(TIME(1000) / opaque(DINT(0)) == TIME());
    CHECK(faults.count == 1);
    CHECK(faults.last_kind == fault_kind::division_by_zero);
    CHECK(LTIME(1s) / 0.0 == LTIME());
    CHECK(faults.count == 2);
  }

  TEST_CASE("comparison with TIME and with std::chrono durations") {
    const TIME a = 1s;
    const TIME b = 1500ms;
    CHECK(a < b);
    CHECK(b > a);
    CHECK(a == 1000ms);
    CHECK(a != b);
    CHECK(a <= 1s);
    CHECK(b >= 1s);
    CHECK(1s < b);
    const LTIME l = 2s;
    CHECK(l > a);  // TIME widens to LTIME
  }

  TEST_CASE("from_ticks builds a duration from a run-time tick count") {
    const auto ms = static_cast<std::uint32_t>(opaque(DINT(2500)).value());
    CHECK(TIME::from_ticks(ms) == 2500ms);
    CHECK(LTIME::from_ticks(42).count() == 42u);
  }
}
