// A REAL converts to an integer in float arithmetic (types/detail/float_to_int.hpp), so that a
// core without a double FPU links no double routines for it. It must give exactly what the
// long double conversion gives: checked against it on every float near a half and on ten
// million random bit patterns (the long double of x86-64 holds x ± 0.5 exactly for every
// float, so there it is the reference).
#include "iecoop_test.hpp"

#include <bit>
#include <cmath>
#include <random>

using namespace iecoop;

namespace {

std::int64_t reference_round(float x) { return detail::round_to_int64(static_cast<long double>(x)); }
std::int64_t reference_trunc(float x) { return detail::trunc_to_int64(static_cast<long double>(x)); }

// The float conversions against the reference; the first float that differs, or none.
struct mismatch {
  bool found = false;
  float x = 0;
};
mismatch compare(float x, mismatch m) {
  if (m.found) return m;
  if (detail::round_to_int64(x) != reference_round(x) || detail::trunc_to_int64(x) != reference_trunc(x)) {
    return {true, x};
  }
  return m;
}

}  // namespace

TEST_SUITE("REAL to integer in float arithmetic") {
  TEST_CASE("the reference holds x + 0.5 exactly here") {
    // The test is only as good as its reference: long double must hold 2^63 + 0.5's neighbours.
    REQUIRE(std::numeric_limits<long double>::digits >= 64);
  }

  TEST_CASE("halves, their neighbours and the edges give what long double gives") {
    mismatch m;
    for (int n = -300000; n <= 300000; ++n) {
      const float half = static_cast<float>(n) + 0.5F;
      for (const float x : {static_cast<float>(n), half, std::nextafter(half, 0.0F), std::nextafter(half, 1e30F),
                            std::nextafter(half, -1e30F)}) {
        m = compare(x, m);
      }
    }
    for (float start : {8388607.0F, 8388608.0F, 16777216.0F, 2147483648.0F, 9223372036854775808.0F}) {
      float up = start, down = start;
      for (int i = 0; i < 64; ++i) {
        m = compare(up, m);
        m = compare(-up, m);
        m = compare(down, m);
        m = compare(-down, m);
        up = std::nextafter(up, 1e38F);
        down = std::nextafter(down, 0.0F);
      }
    }
    for (const float x : {0.0F, -0.0F, std::numeric_limits<float>::denorm_min(), std::numeric_limits<float>::min(),
                          std::numeric_limits<float>::max(), std::numeric_limits<float>::lowest(),
                          std::numeric_limits<float>::infinity(), -std::numeric_limits<float>::infinity(),
                          std::numeric_limits<float>::quiet_NaN(), 0.49999997F, -0.49999997F}) {
      m = compare(x, m);
    }
    CHECK_MESSAGE(!m.found, "first difference at ", m.x);
  }

  TEST_CASE("ten million random floats give what long double gives") {
    std::mt19937 random(20261207);  // fixed seed: the same floats every run
    mismatch m;
    for (int i = 0; i < 10'000'000; ++i) m = compare(std::bit_cast<float>(static_cast<std::uint32_t>(random())), m);
    CHECK_MESSAGE(!m.found, "first difference at ", m.x);
  }

  TEST_CASE("the conversions a port writes") {
    CHECK(REAL_TO_INT(REAL(2.5F)) == INT(3));
    CHECK(REAL_TO_INT(REAL(-2.5F)) == INT(-3));
    CHECK(REAL_TO_INT(REAL(2.4999998F)) == INT(2));
    CHECK(REAL_TO_DINT(REAL(8388609.0F)) == DINT(8388609));  // x + 0.5 in float would give 8388610
    CHECK(REAL_TO_DINT(REAL(-8388609.0F)) == DINT(-8388609));
    CHECK(REAL_TO_LINT(REAL(1e19F)) == LINT(std::numeric_limits<std::int64_t>::max()));
    CHECK(REAL_TO_ULINT(REAL(1e19F)) == ULINT(static_cast<std::uint64_t>(1e19F)));  // 2^63 .. 2^64: unsigned
    CHECK(REAL_TO_INT(REAL(std::numeric_limits<float>::quiet_NaN())) == INT(0));
    CHECK(TRUNC(REAL(-7.9F)) == DINT(-7));
    CHECK(TRUNC_INT(REAL(7.9F)) == INT(7));
    CHECK(REAL_TO_TIME(REAL(1500.5F)) == "T#1501ms"_iec);
    // And at compile time.
    static_assert(REAL_TO_INT(REAL(-1.5F)) == INT(-2));
    static_assert(detail::round_to_int64(8388609.0F) == 8388609);
  }
}
