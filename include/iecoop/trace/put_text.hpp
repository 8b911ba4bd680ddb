// SPDX-License-Identifier: MIT
// iecoop/trace/put_text.hpp — numbers as text for the trace writers, through a `put(std::string_view)`,
// without the heap: each number is formatted into a buffer on the stack. Integers only: a REAL
// is written as its type's text (trace_view::text()), so that std::to_chars for floating point,
// which lives in the compiled libstdc++ and not in a firmware's link, is needed only where a
// REAL or LREAL is traced.
// IWYU pragma: private, include <iecoop/trace.hpp>
#pragma once

#include <cstddef>
#include <cstdint>
#include <string_view>

#include <iecoop/config.hpp>
#include <iecoop/detail/constant_division.hpp>
#include <iecoop/trace/channels.hpp>
#include <iecoop/types/literal_text.hpp>

#include <iecoop/detail/push_macros.hpp>

namespace iecoop::detail {

/// In the value's own width, as to_text writes integers (no 64-bit division where it fits 32).
template <class Put>
void put_unsigned(Put& put, std::uint64_t value) {
  char text[20];
  const char* const end =
      value <= 0xFFFF'FFFFU ? write_unsigned(text, static_cast<std::uint32_t>(value)) : write_unsigned(text, value);
  put(std::string_view(text, static_cast<std::size_t>(end - text)));
}

template <class Put>
void put_signed(Put& put, std::int64_t value) {
  if (value < 0) put("-");
  // The magnitude, INT64_MIN's too.
  put_unsigned(put,
               value < 0 ? std::uint64_t{0} - static_cast<std::uint64_t>(value) : static_cast<std::uint64_t>(value));
}

/// `ns` in units of `Unit` ns (a power of ten up to 1 s), exactly: `21000`, `0.25`,
/// `0.000000001`. The unit is a constant, so that a 32-bit core divides by its reciprocal
/// (detail/constant_division.hpp), and the fraction, below 1 s, in 32 bits.
template <std::uint64_t Unit, class Put>
void put_decimal(Put& put, std::uint64_t ns) {
  static_assert(Unit >= 1 && Unit <= 1'000'000'000, "iecoop: internal: a unit from 1 ns to 1 s");
  const std::uint64_t whole = divide_by<Unit>(ns);
  put_unsigned(put, whole);
  auto fraction = static_cast<std::uint32_t>(ns - whole * Unit);
  if (fraction == 0) return;
  char digits[10] = {'.'};
  std::size_t length = 1;
  for (auto place = static_cast<std::uint32_t>(Unit / 10); place > 0; place /= 10) {
    digits[length++] = static_cast<char>('0' + fraction / place);
    fraction %= place;
  }
  while (digits[length - 1] == '0') --length;
  put(std::string_view(digits, length));
}

/// `ns` as milliseconds: `21000`, or `0.25` when it is no whole number of them.
template <class Put>
void put_milliseconds(Put& put, std::uint64_t ns) {
  put_decimal<1'000'000>(put, ns);
}

/// `ns` as seconds, exactly: `21`, `1.5`, `0.000000001`.
template <class Put>
void put_seconds(Put& put, std::uint64_t ns) {
  put_decimal<1'000'000'000>(put, ns);
}

/// A recorded value but a REAL or LREAL as a number: BOOL 0 or 1, integers and counts in
/// decimal. (A REAL is written as its type's text, trace_view::text(): the shortest text that
/// reads back as the same REAL, `0.1`, not the double it widens to, 0.10000000149011612.)
template <class Put>
void put_number(Put& put, const trace_value& value) {
  if (value.is_signed) {
    put_signed(put, value.i);
  } else {
    put_unsigned(put, value.u);
  }
}

}  // namespace iecoop::detail

#include <iecoop/detail/pop_macros.hpp>
