// SPDX-License-Identifier: MIT
// iecoop/sfc/detail/bit_set.hpp — the bit sets a chart keeps its active steps, the step events of
// a scan and its actions' Q in: a scan then costs per active step and per running action, not
// per element of the chart.
// IWYU pragma: private, include <iecoop/sfc/chart.hpp>
#pragma once

#include <array>
#include <bit>
#include <cstddef>
#include <cstdint>

namespace iecoop::sfc::detail {

/// N bits, in 64-bit words (at least one).
template <std::size_t N>
using bits = std::array<std::uint64_t, (N + 63) / 64 == 0 ? 1 : (N + 63) / 64>;

template <std::size_t N>
constexpr bool test_bit(const bits<N>& b, std::size_t i) noexcept {
  return ((b[i / 64] >> (i % 64)) & 1u) != 0;
}
template <std::size_t N>
constexpr void set_bit(bits<N>& b, std::size_t i) noexcept {
  b[i / 64] |= std::uint64_t{1} << (i % 64);
}
template <std::size_t N>
constexpr void clear_bit(bits<N>& b, std::size_t i) noexcept {
  b[i / 64] &= ~(std::uint64_t{1} << (i % 64));
}
/// The bits of word w that can be set (below N): a bit set never has others, and saying so
/// lets the compiler see that an index stays below N (g++ 12 -O2 -Warray-bounds otherwise warns
/// about the table of a chart of a few steps).
template <std::size_t N>
constexpr std::uint64_t valid_bits(std::size_t w) noexcept {
  return (w + 1) * 64 <= N ? ~std::uint64_t{0} : w * 64 >= N ? 0 : (std::uint64_t{1} << (N - w * 64)) - 1;
}
/// Calls table[i](args...) for every set bit i, lowest first.
template <std::size_t N, class Table, class... Args>
void for_each_bit(const bits<N>& b, const Table& table, Args&... args) {
  for (std::size_t w = 0; w < b.size(); ++w) {
    for (std::uint64_t m = b[w] & valid_bits<N>(w); m != 0; m &= m - 1) {
      table[w * 64 + static_cast<std::size_t>(std::countr_zero(m))](args...);
    }
  }
}
template <std::size_t N>
constexpr bool any(const bits<N>& b) noexcept {
  for (const std::uint64_t w : b) {
    if (w != 0) return true;
  }
  return false;
}

}  // namespace iecoop::sfc::detail
