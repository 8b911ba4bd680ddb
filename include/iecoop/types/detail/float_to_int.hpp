// SPDX-License-Identifier: MIT
// iecoop/types/detail/float_to_int.hpp — floating-point to integer without undefined behaviour.
// A REAL (float) converts in float arithmetic only, an LREAL through long double: on a core
// without a double-precision FPU (Cortex-M0+, M3, M4F, M33) a REAL conversion then needs none
// of the soft-float library's double routines (about 3 KB of flash).
// IWYU pragma: private, include <iecoop/types/convert.hpp>
#pragma once

#include <bit>
#include <cstdint>
#include <limits>

namespace iecoop::detail {

/// The int64 range as long double bounds: at or beyond them, results saturate.
inline constexpr long double int64_upper = 9223372036854775807.0L;
inline constexpr long double int64_lower = -9223372036854775807.0L;

/// Truncates toward zero; NaN gives 0, values beyond the int64 range saturate.
constexpr std::int64_t trunc_to_int64(long double x) noexcept {
  if (x != x) return 0;  // NaN
  if (x >= int64_upper) return std::numeric_limits<std::int64_t>::max();
  if (x <= int64_lower) return std::numeric_limits<std::int64_t>::min();
  return static_cast<std::int64_t>(x);
}
constexpr std::int64_t trunc_to_int64(double x) noexcept { return trunc_to_int64(static_cast<long double>(x)); }
/// A whole float of magnitude 2^23 or more (below 2^64), from its bits: its mantissa shifted
/// by its exponent. (Not a conversion: libgcc converts a float to a 64-bit integer through
/// double, and that would bring the double routines back on a core without a double FPU.)
constexpr std::uint64_t whole_float_magnitude(float x) noexcept {
  const auto bits = std::bit_cast<std::uint32_t>(x);
  const auto exponent = static_cast<int>((bits >> 23) & 0xFFU) - 150;  // x = mantissa x 2^exponent
  return static_cast<std::uint64_t>((bits & 0x7FFFFFU) | 0x800000U) << exponent;
}

/// The same for a float, in float arithmetic: the floats at the bounds are ±2^63 (no float
/// lies between 2^63 - 1 and 2^63), so the results are those of the long double version.
constexpr std::int64_t trunc_to_int64(float x) noexcept {
  if (x != x) return 0;  // NaN
  if (x >= 9223372036854775808.0F) return std::numeric_limits<std::int64_t>::max();
  if (x <= -9223372036854775808.0F) return std::numeric_limits<std::int64_t>::min();
  if (x < 2147483648.0F && x > -2147483648.0F) return static_cast<std::int32_t>(x);
  const auto magnitude = static_cast<std::int64_t>(whole_float_magnitude(x));  // 2^31 .. 2^63: whole
  return x < 0 ? -magnitude : magnitude;
}

/// Rounds to nearest, halves away from zero (CODESYS: REAL_TO_INT(1.5) = 2,
/// REAL_TO_INT(-1.5) = -2); NaN gives 0, values beyond the int64 range saturate.
constexpr std::int64_t round_to_int64(long double x) noexcept {
  if (x != x) return 0;
  return trunc_to_int64(x < 0 ? x - 0.5L : x + 0.5L);
}
constexpr std::int64_t round_to_int64(double x) noexcept { return round_to_int64(static_cast<long double>(x)); }
/// The same for a float, in float arithmetic. Not x ± 0.5, which a float rounds where it has
/// no halves (from 2^23 up: 8388609 + 0.5 is 8388610 in float): the whole part, then the
/// fraction it leaves, which is exact below 2^23; from there up every float is a whole number.
constexpr std::int64_t round_to_int64(float x) noexcept {
  const std::int64_t whole = trunc_to_int64(x);  // NaN: 0
  if (!(x < 8388608.0F && x > -8388608.0F)) return whole;
  const float fraction = x - static_cast<float>(static_cast<std::int32_t>(whole));
  if (fraction >= 0.5F) return whole + 1;
  if (fraction <= -0.5F) return whole - 1;
  return whole;
}

}  // namespace iecoop::detail
