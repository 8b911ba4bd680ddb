// SPDX-License-Identifier: MIT
// iecoop/util/bcd_conversions.hpp — the CODESYS Util library's BCD_TO_INT and INT_TO_BCD: one
// byte of two BCD digits (16#49) and the INT it stands for (49).
//
//     i := BCD_TO_INT(73);     i = BCD_TO_INT(73);      (* 16#49: 49 *)
//     l := BCD_TO_INT(15);     l = BCD_TO_INT(15);      (* 16#0F is no BCD: -1 *)
//     b := INT_TO_BCD(49);     b = INT_TO_BCD(49);      (* 16#49 = 73 *)
//     b := INT_TO_BCD(100);    b = INT_TO_BCD(100);     (* out of 0..99: 255 *)
#pragma once

#include <cstdint>

#include <iecoop/config.hpp>
#include <iecoop/types/elementary.hpp>

#include <iecoop/detail/push_macros.hpp>

namespace iecoop {

/// FUNCTION BCD_TO_INT : INT — the two BCD digits of B as 0..99; -1 if a digit is above 9.
[[nodiscard]] constexpr INT BCD_TO_INT(BYTE B) noexcept {
  const unsigned high = B.value() >> 4U;
  const unsigned low = B.value() & 0x0FU;
  if (high > 9U || low > 9U) return INT(-1);
  return INT(static_cast<std::int16_t>(high * 10U + low));
}

/// FUNCTION INT_TO_BCD : BYTE — I (0..99) as two BCD digits; 255 for a value out of 0..99.
[[nodiscard]] constexpr BYTE INT_TO_BCD(INT I) noexcept {
  const int i = I.value();
  if (i < 0 || i > 99) return BYTE(255);
  return BYTE(static_cast<std::uint8_t>(((i / 10) << 4) | (i % 10)));
}

}  // namespace iecoop

#include <iecoop/detail/pop_macros.hpp>
