// 64-bit division by a constant without a division (<iecoop/detail/constant_division.hpp>):
// the reciprocal path, which 32-bit targets take, against the compiler's `/` for divisors of
// every kind (the unit conversions of TIME and LTIME, small odd and even ones, the largest, one
// above 2^63) and dividends around every multiple boundary, the extremes and random ones. A
// 64-bit host would take `/` itself, so the test calls divide_by_reciprocal directly.
#include "iecoop_test.hpp"

#include <iecoop/detail/constant_division.hpp>
#include <iecoop/types/time.hpp>

#include <cstdint>
#include <limits>
#include <random>

using namespace iecoop;

namespace {

constexpr std::uint64_t max64 = std::numeric_limits<std::uint64_t>::max();

// Every check of one divisor; returns how many dividends were checked (so a test that checked
// none fails).
template <std::uint64_t D>
int check_divisor(std::mt19937_64& random) {
  int checked = 0;
  const auto check = [&](std::uint64_t x) {
    const std::uint64_t expected = x / D;
    const std::uint64_t got = detail::divide_by_reciprocal<D>(x);
    if (got != expected) {
      FAIL_CHECK("divisor " << D << ", dividend " << x << ": " << got << " instead of " << expected);
    }
    ++checked;
  };
  for (std::uint64_t x = 0; x < 2000; ++x) check(x);
  for (std::uint64_t k = 1; k < 64; ++k) {  // around multiples of D and the powers of 2
    const std::uint64_t multiple = (max64 / D / (std::uint64_t{1} << k)) * D;
    for (std::uint64_t x : {multiple - 1, multiple, multiple + 1, (std::uint64_t{1} << k) - 1, std::uint64_t{1} << k}) {
      check(x);
    }
  }
  for (std::uint64_t x = max64 - 2000; x != 0; ++x) check(x);  // up to 2^64 - 1
  const std::uint64_t last_multiple = max64 / D * D;
  check(last_multiple - 1);
  check(last_multiple);
  for (int i = 0; i < 20000; ++i) {
    const std::uint64_t x = random();
    check(x);
    check(x >> (i % 64));  // small ones too
  }
  return checked;
}

// The compile-time path and the reciprocal agree in a constant expression.
static_assert(detail::divide_by<1000000>(std::uint64_t{123456789012}) == 123456);
static_assert(detail::divide_by_reciprocal<1000000>(std::uint64_t{123456789012}) == 123456);
static_assert(detail::divide_by_reciprocal<3>(max64) == max64 / 3);
static_assert(detail::divide_by_reciprocal<(std::uint64_t{1} << 63) + 1>(max64) == 1);
static_assert(detail::multiply_high(max64, max64) == max64 - 1);

}  // namespace

TEST_CASE("constant_division: the reciprocal gives floor(x / D) for every kind of divisor") {
  std::mt19937_64 random(20261207);
  int checked = 0;
  checked += check_divisor<1000000>(random);  // LTIME (ns) to TIME (ms)
  checked += check_divisor<1000>(random);
  checked += check_divisor<1000000000>(random);
  checked += check_divisor<100>(random);  // TwinCAT's 100 ns units
  checked += check_divisor<3>(random);
  checked += check_divisor<7>(random);
  checked += check_divisor<10>(random);
  checked += check_divisor<641>(random);
  checked += check_divisor<1024>(random);  // a power of 2: a shift
  checked += check_divisor<1>(random);
  checked += check_divisor<86400000000000>(random);  // a day in ns
  checked += check_divisor<(std::uint64_t{1} << 63) + 1>(random);
  checked += check_divisor<max64 - 1>(random);
  checked += check_divisor<max64>(random);
  CHECK(checked > 14 * 40000);
}

TEST_CASE("constant_division: the long division gives floor(n / d) for run-time divisors") {
  std::mt19937_64 random(7);
  int checked = 0;
  const auto check = [&](std::uint64_t n, std::uint64_t d) {
    if (detail::divide_by_steps(n, d) != n / d) FAIL_CHECK("dividend " << n << ", divisor " << d);
    CHECK(detail::divide_u64(n, d) == n / d);
    ++checked;
  };
  for (std::uint64_t d :
       {std::uint64_t{1}, std::uint64_t{2}, std::uint64_t{3}, std::uint64_t{100}, std::uint64_t{1000000},
        std::uint64_t{0xFFFFFFFFU}, std::uint64_t{0x100000000ULL}, (std::uint64_t{1} << 63) + 1, max64}) {
    for (std::uint64_t n : {std::uint64_t{0}, std::uint64_t{1}, d - 1, d, d + 1, max64 - 1, max64, max64 / 2 + 1})
      check(n, d);
  }
  for (int i = 0; i < 20000; ++i) {
    const std::uint64_t n = random();
    const std::uint64_t d = random() >> (i % 64);
    if (d != 0) check(n, d);
  }
  CHECK(checked > 19000);
}
static_assert(detail::divide_by_steps(max64, 3) == max64 / 3);
static_assert(detail::divide_by_steps(1000, 1001) == 0);

TEST_CASE("constant_division: LTIME to TIME truncates to whole milliseconds and wraps, as before") {
  CHECK(TIME(LTIME::from_ticks(999999)).count() == 0U);
  CHECK(TIME(LTIME::from_ticks(1000000)).count() == 1U);
  CHECK(TIME(LTIME::from_ticks(4294967296000000ULL)).count() == 0U);  // 2^32 ms wraps to 0
  CHECK(TIME(LTIME::from_ticks(max64)).count() == static_cast<std::uint32_t>(max64 / 1000000));
  CHECK(LTIME(TIME(1234)).count() == 1234000000ULL);
}

TEST_CASE("constant_division: divide_toward_zero truncates toward zero, as ST's integer division") {
  // The 32-bit target's path, on the host: against C++'s `/`.
  const auto check = [](std::int64_t n, std::int64_t d) {
    REQUIRE(detail::divide_toward_zero_portable(n, d) == n / d);
    REQUIRE(detail::divide_toward_zero(n, d) == n / d);
  };
  CHECK(detail::divide_toward_zero_portable(7, 2) == 3);
  CHECK(detail::divide_toward_zero_portable(-7, 2) == -3);  // toward zero, not down
  CHECK(detail::divide_toward_zero_portable(0, 5) == 0);
  CHECK(detail::divide_toward_zero_portable(-4294836225LL, 65535) == -65535);  // CHARCURVE's largest product
  check(std::numeric_limits<std::int64_t>::min() + 1, 1);
  check(std::numeric_limits<std::int64_t>::max(), 7);
  check(-(std::int64_t{1} << 40), 3);
  std::uint64_t state = 0x9E3779B97F4A7C15ULL;
  for (int i = 0; i < 20000; ++i) {
    state = state * 6364136223846793005ULL + 1442695040888963407ULL;
    const auto n = static_cast<std::int64_t>(state) >> (i % 40);
    const auto d = static_cast<std::int64_t>((state >> 17) % 100000U) + 1;
    check(n, d);
  }
}
