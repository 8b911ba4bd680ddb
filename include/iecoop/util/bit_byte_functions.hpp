// SPDX-License-Identifier: MIT
// iecoop/util/bit_byte_functions.hpp — the CODESYS Util library's bit functions EXTRACT, PACK,
// PUTBIT and UNPACK.
//
//     FLAG := EXTRACT(X := 81, N := 4);            FLAG = EXTRACT(81, 4);              (TRUE)
//     byOut := PACK(b0, b1, b2, b3, b4, b5, b6, b7); byOut = PACK(b0, b1, b2, b3, b4, b5, b6, b7);
//     dw := PUTBIT(dw, 4, TRUE);                   dw = PUTBIT(dw, 4, TRUE);
//     fbBits(B := byIn);  IF fbBits.B3 THEN ...    fbBits("B"_ = byIn);  if (fbBits.B3) ...
//
// Bits count from 0, the least significant. A bit number beyond the DWORD (N >= 32), which the
// documentation leaves open, reads as FALSE (EXTRACT) and changes nothing (PUTBIT).
#pragma once

#include <cstdint>

#include <iecoop/config.hpp>
#include <iecoop/pou/call_interface.hpp>
#include <iecoop/pou/function_block.hpp>
#include <iecoop/pou/variables.hpp>
#include <iecoop/types/elementary.hpp>

#include <iecoop/detail/push_macros.hpp>

namespace iecoop {

/// FUNCTION EXTRACT : BOOL — bit N of X (FALSE for N >= 32).
[[nodiscard]] constexpr BOOL EXTRACT(DWORD X, BYTE N) noexcept {
  const unsigned n = N.value();
  return BOOL(n < 32U && ((X.value() >> n) & 1U) != 0U);
}

/// FUNCTION PACK : BYTE — B0 (bit 0) .. B7 (bit 7) as one BYTE.
[[nodiscard]] constexpr BYTE PACK(BOOL B0, BOOL B1, BOOL B2, BOOL B3, BOOL B4, BOOL B5, BOOL B6, BOOL B7) noexcept {
  const unsigned value = (B0 ? 0x01U : 0U) | (B1 ? 0x02U : 0U) | (B2 ? 0x04U : 0U) | (B3 ? 0x08U : 0U) |
                         (B4 ? 0x10U : 0U) | (B5 ? 0x20U : 0U) | (B6 ? 0x40U : 0U) | (B7 ? 0x80U : 0U);
  return BYTE(static_cast<std::uint8_t>(value));
}

/// FUNCTION PUTBIT : DWORD — X with bit N set to B (X unchanged for N >= 32).
[[nodiscard]] constexpr DWORD PUTBIT(DWORD X, BYTE N, BOOL B) noexcept {
  const unsigned n = N.value();
  if (n >= 32U) return X;
  const std::uint32_t mask = std::uint32_t{1} << n;
  return DWORD(B ? (X.value() | mask) : (X.value() & ~mask));
}

/// FUNCTION_BLOCK UNPACK — the eight bits of B as B0 (bit 0) .. B7 (bit 7).
class UNPACK : public function_block<UNPACK> {
 public:
  BYTE B;                      ///< VAR_INPUT: the value
  read_only<BOOL, UNPACK> B0;  ///< VAR_OUTPUT: bit 0
  read_only<BOOL, UNPACK> B1;  ///< VAR_OUTPUT: bit 1
  read_only<BOOL, UNPACK> B2;  ///< VAR_OUTPUT: bit 2
  read_only<BOOL, UNPACK> B3;  ///< VAR_OUTPUT: bit 3
  read_only<BOOL, UNPACK> B4;  ///< VAR_OUTPUT: bit 4
  read_only<BOOL, UNPACK> B5;  ///< VAR_OUTPUT: bit 5
  read_only<BOOL, UNPACK> B6;  ///< VAR_OUTPUT: bit 6
  read_only<BOOL, UNPACK> B7;  ///< VAR_OUTPUT: bit 7

  using VAR_INPUT = pins<&UNPACK::B>;
  using VAR_OUTPUT =
      pins<&UNPACK::B0, &UNPACK::B1, &UNPACK::B2, &UNPACK::B3, &UNPACK::B4, &UNPACK::B5, &UNPACK::B6, &UNPACK::B7>;

 private:
  friend struct block_access;

  void body() noexcept {
    const unsigned b = B.value();
    B0 = BOOL((b & 0x01U) != 0U);
    B1 = BOOL((b & 0x02U) != 0U);
    B2 = BOOL((b & 0x04U) != 0U);
    B3 = BOOL((b & 0x08U) != 0U);
    B4 = BOOL((b & 0x10U) != 0U);
    B5 = BOOL((b & 0x20U) != 0U);
    B6 = BOOL((b & 0x40U) != 0U);
    B7 = BOOL((b & 0x80U) != 0U);
  }
};

}  // namespace iecoop

#include <iecoop/detail/pop_macros.hpp>
