// SPDX-License-Identifier: MIT
// iecoop/trace/put_text.hpp — numbers as text for the trace writers, through a `put(std::string_view)`,
// without the heap: each number is formatted into a buffer on the stack. Integers only: a REAL
// is written as its type's text (trace_view::text()), so that std::to_chars for floating point,
// which lives in the compiled libstdc++ and not in a firmware's link, is needed only where a
// REAL or LREAL is traced.
// IWYU pragma: private, include <iecoop/trace.hpp>
#pragma once

#include <charconv>
#include <cstddef>
#include <cstdint>
#include <string_view>

#include <iecoop/config.hpp>
#include <iecoop/trace/channels.hpp>

#include <iecoop/detail/push_macros.hpp>

namespace iecoop::detail {

template <class Put>
void put_unsigned(Put& put, std::uint64_t value) {
  char text[20];
  const auto result = std::to_chars(text, text + sizeof text, value);
  put(std::string_view(text, static_cast<std::size_t>(result.ptr - text)));
}

template <class Put>
void put_signed(Put& put, std::int64_t value) {
  char text[21];
  const auto result = std::to_chars(text, text + sizeof text, value);
  put(std::string_view(text, static_cast<std::size_t>(result.ptr - text)));
}

/// `ns` as milliseconds: `21000`, or `0.25` when it is no whole number of them.
template <class Put>
void put_milliseconds(Put& put, std::uint64_t ns) {
  put_unsigned(put, ns / 1'000'000);
  std::uint64_t fraction = ns % 1'000'000;
  if (fraction == 0) return;
  char digits[7] = {'.', '0', '0', '0', '0', '0', '0'};
  for (std::size_t d = 6; d >= 1; --d) {
    digits[d] = static_cast<char>('0' + fraction % 10);
    fraction /= 10;
  }
  std::size_t length = 7;
  while (digits[length - 1] == '0') --length;
  put(std::string_view(digits, length));
}

/// `ns` as seconds, exactly: `21`, `1.5`, `0.000000001`.
template <class Put>
void put_seconds(Put& put, std::uint64_t ns) {
  put_unsigned(put, ns / 1'000'000'000);
  std::uint64_t fraction = ns % 1'000'000'000;
  if (fraction == 0) return;
  char digits[10] = {'.', '0', '0', '0', '0', '0', '0', '0', '0', '0'};
  for (std::size_t d = 9; d >= 1; --d) {
    digits[d] = static_cast<char>('0' + fraction % 10);
    fraction /= 10;
  }
  std::size_t length = 10;
  while (digits[length - 1] == '0') --length;
  put(std::string_view(digits, length));
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
