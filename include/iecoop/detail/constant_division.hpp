// SPDX-License-Identifier: MIT
// iecoop/detail/constant_division.hpp — a 64-bit unsigned integer divided by a constant, without
// a division instruction or a call to the compiler's division routine.
// IWYU pragma: private, include <iecoop/iecoop.hpp>
//
// Why: a 32-bit core has no 64-bit divide instruction (a Cortex-M0+ has no divide instruction
// at all), so `ns / 1000000` calls libgcc's __aeabi_uldivmod, hundreds of cycles on a small core,
// and the cycle clock does that conversion (LTIME to TIME) in every task cycle. A compiler for a
// 64-bit host already turns a division by a constant into a multiplication by its reciprocal;
// for a 32-bit target it does not, for 64-bit operands. divide_by<D>(x) does it here: the
// high half of a 64 x 64-bit product, made from four 32 x 32-bit products (one UMULL each on a
// Cortex-M3 and later), and two shifts (Granlund and Montgomery, "Division by invariant
// integers using multiplication", PLDI 1994, the method for every divisor and every dividend).
#pragma once

#include <cstdint>
#include <type_traits>

namespace iecoop::detail {

/// The high 64 bits of the 128-bit product a x b, from 32-bit halves.
[[nodiscard]] constexpr std::uint64_t multiply_high(std::uint64_t a, std::uint64_t b) noexcept {
  const std::uint64_t a_low = a & 0xFFFFFFFFU;
  const std::uint64_t a_high = a >> 32;
  const std::uint64_t b_low = b & 0xFFFFFFFFU;
  const std::uint64_t b_high = b >> 32;
  const std::uint64_t low_low = a_low * b_low;
  const std::uint64_t low_high = a_low * b_high;
  const std::uint64_t high_low = a_high * b_low;
  const std::uint64_t middle = (low_low >> 32) + (low_high & 0xFFFFFFFFU) + (high_low & 0xFFFFFFFFU);
  return a_high * b_high + (low_high >> 32) + (high_low >> 32) + (middle >> 32);
}

/// The reciprocal of D for divide_by_reciprocal<D>: l = ceil(log2 D), and
/// m = floor(2^64 x (2^l - D) / D) + 1, so that (2^64 + m) / 2^(64 + l) is just above 1 / D.
template <std::uint64_t D>
struct reciprocal {
  static_assert(D > 1 && (D & (D - 1)) != 0, "iecoop: internal: a reciprocal is for divisors other than powers of 2");
  static constexpr unsigned shift = [] {
    unsigned l = 0;
    while (l < 64 && (std::uint64_t{1} << l) < D) ++l;
    return l;  // 1 < D < 2^64 and not a power of 2: 2^(l-1) < D < 2^l (l = 64: D > 2^63)
  }();
  static constexpr std::uint64_t factor = [] {
    // (2^l - D) < D: divide (2^l - D) x 2^64 by D one bit at a time, as on paper.
    const std::uint64_t two_l_minus_d = shift == 64 ? (~D + 1) : (std::uint64_t{1} << shift) - D;
    std::uint64_t remainder = two_l_minus_d;
    std::uint64_t quotient = 0;
    for (int bit = 0; bit < 64; ++bit) {
      const bool carry = (remainder >> 63) != 0;  // remainder x 2 overflows 64 bits
      remainder <<= 1;
      quotient <<= 1;
      if (carry || remainder >= D) {
        remainder -= D;  // wraps back into range where it overflowed: the true value is below 2 D
        quotient |= 1;
      }
    }
    return quotient + 1;
  }();
};

/// floor(x / D) by the reciprocal, on any target (tested against `/` for every kind of
/// divisor: tests/unit/constant_division_test.cpp).
template <std::uint64_t D>
[[nodiscard]] constexpr std::uint64_t divide_by_reciprocal(std::uint64_t x) noexcept {
  static_assert(D != 0, "iecoop: internal: division by zero");
  if constexpr (D == 1) {
    return x;
  } else if constexpr ((D & (D - 1)) == 0) {
    unsigned s = 0;
    while ((std::uint64_t{1} << s) != D) ++s;
    return x >> s;
  } else {
    const std::uint64_t t = multiply_high(reciprocal<D>::factor, x);
    return (t + ((x - t) >> 1)) >> (reciprocal<D>::shift - 1);
  }
}

/// floor(x / D): the compiler's own division where it has a 64 x 64-bit multiplication (a
/// 64-bit host, where it does the same with one instruction) or the value is a constant,
/// divide_by_reciprocal elsewhere.
template <std::uint64_t D>
[[nodiscard]] constexpr std::uint64_t divide_by(std::uint64_t x) noexcept {
#if defined(__SIZEOF_INT128__)
  return x / D;
#else
  if (std::is_constant_evaluated()) return x / D;
  return divide_by_reciprocal<D>(x);
#endif
}

/// floor(n / d), d > 0, by binary long division: 64 steps of a shift and a compare (tested
/// against `/`: tests/unit/constant_division_test.cpp).
[[nodiscard]] constexpr std::uint64_t divide_by_steps(std::uint64_t n, std::uint64_t d) noexcept {
  std::uint64_t quotient = 0;
  std::uint64_t remainder = 0;
  for (int bit = 63; bit >= 0; --bit) {
    const bool carry = (remainder >> 63) != 0;  // remainder x 2 overflows 64 bits
    remainder = (remainder << 1) | ((n >> bit) & 1U);
    if (carry || remainder >= d) {
      remainder -= d;
      quotient |= std::uint64_t{1} << bit;
    }
  }
  return quotient;
}

/// floor(n / d), d > 0, the way a 32-bit target does it: one 32-bit division where both fit 32
/// bits, else divide_by_steps.
[[nodiscard]] constexpr std::uint64_t divide_u64_portable(std::uint64_t n, std::uint64_t d) noexcept {
  if ((n >> 32) == 0 && (d >> 32) == 0) {
    return static_cast<std::uint32_t>(n) / static_cast<std::uint32_t>(d);
  }
  return divide_by_steps(n, d);
}
/// floor(n / d) for a divisor known only at run time (d > 0), without libgcc's 64-bit division
/// routine (700 bytes of flash on a Cortex-M3): the compiler's division on a 64-bit host, else
/// divide_u64_portable. For the scheduler's rare paths (the releases a late task missed, a
/// freewheeling task's pause) and the Util blocks' divisions, whose values mostly fit 32 bits;
/// a quotient of wider values takes 64 steps.
[[nodiscard]] constexpr std::uint64_t divide_u64(std::uint64_t n, std::uint64_t d) noexcept {
#if defined(__SIZEOF_INT128__)
  return n / d;
#else
  return divide_u64_portable(n, d);
#endif
}

/// n / d truncated toward zero (as ST's integer division), d > 0, the way a 32-bit target does
/// it: divide_u64_portable of the magnitudes. (Tested on the host against `/`.)
[[nodiscard]] constexpr std::int64_t divide_toward_zero_portable(std::int64_t n, std::int64_t d) noexcept {
  const bool negative = n < 0;
  const std::uint64_t magnitude = negative ? 0U - static_cast<std::uint64_t>(n) : static_cast<std::uint64_t>(n);
  const std::uint64_t quotient = divide_u64_portable(magnitude, static_cast<std::uint64_t>(d));
  return negative ? -static_cast<std::int64_t>(quotient) : static_cast<std::int64_t>(quotient);
}

/// n / d truncated toward zero (as ST's integer division), d > 0, without libgcc's 64-bit
/// division on a 32-bit target (the Util blocks' interpolations, ramps and means): the
/// compiler's division on a 64-bit host, else divide_toward_zero_portable.
[[nodiscard]] constexpr std::int64_t divide_toward_zero(std::int64_t n, std::int64_t d) noexcept {
#if defined(__SIZEOF_INT128__)
  return n / d;
#else
  return divide_toward_zero_portable(n, d);
#endif
}

}  // namespace iecoop::detail
