// SPDX-License-Identifier: MIT
// iecoop/types/detail/float_to_int.hpp — floating-point to integer without undefined behaviour.
// IWYU pragma: private, include <iecoop/types/convert.hpp>
#pragma once

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

/// Rounds to nearest, halves away from zero (CODESYS: REAL_TO_INT(1.5) = 2,
/// REAL_TO_INT(-1.5) = -2); NaN gives 0, values beyond the int64 range saturate.
constexpr std::int64_t round_to_int64(long double x) noexcept {
  if (x != x) return 0;
  return trunc_to_int64(x < 0 ? x - 0.5L : x + 0.5L);
}

}  // namespace iecoop::detail
