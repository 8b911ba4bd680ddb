// embedded/console.hpp — how the firmware examples print their result: whole lines of text,
// integers, IEC values, with no printf and no buffer beyond one value's text.
//
// On the target the text goes out through semihosting (the host's stdout under QEMU); built
// for the host, the same example writes to stdout, so both builds of an example can be
// checked against the same expected output.
#pragma once

#include <concepts>
#include <cstddef>
#include <cstdint>
#include <string_view>

#include <iecoop/types/elementary.hpp>
#include <iecoop/types/literal_text.hpp>
#include <iecoop/types/time.hpp>

#if defined(__arm__)
#include "semihosting.hpp"
#else
#include <cstdio>
#endif

namespace firmware {

inline void put(std::string_view text) noexcept {
#if defined(__arm__)
  semihosting::write(text);
#else
  std::fwrite(text.data(), 1, text.size(), stdout);
#endif
}

#if defined(__arm__) && defined(__GNUC__) && !defined(__clang__)
/// The length of NUL-terminated `text`, counted here: GCC would turn the loop into a call of
/// newlib's strlen (92 bytes of flash on a Cortex-M3, which nothing else in an image may need;
/// the attribute is GCC's, the toolchain docs/embedded.md names).
[[gnu::optimize("no-tree-loop-distribute-patterns")]] inline std::size_t length_of(const char* text) noexcept {
  std::size_t n = 0;
  while (text[n] != '\0') ++n;
  return n;
}
inline void put(const char* text) noexcept { put(std::string_view(text, length_of(text))); }
#else
inline void put(const char* text) noexcept { put(std::string_view(text)); }
#endif

/// An IEC integer (INT, DINT, WORD, ...) or BOOL as ST writes it: iecoop::to_text, on the stack.
/// Not inlined: the text of a 64-bit number divides in software, which the division check
/// (cmake/check_divisions.cmake) allows in firmware::put, not in the caller.
template <class T>
  requires(iecoop::AnyInteger<T> || std::same_as<T, iecoop::BOOL>)
[[gnu::noinline]] void put(T value) noexcept {
  char text[iecoop::max_text_length<T>];
  put(std::string_view(text, static_cast<std::size_t>(iecoop::to_text(text, value) - text)));
}

/// A C++ integer in decimal, as the IEC integer of its signedness and (at least 32-bit) width.
template <std::integral I>
  requires(!std::same_as<I, bool> && !std::same_as<I, char>)
void put(I value) noexcept {
  if constexpr (std::signed_integral<I>) {
    if constexpr (sizeof(I) <= 4) {
      put(iecoop::DINT(static_cast<std::int32_t>(value)));
    } else {
      put(iecoop::LINT(static_cast<std::int64_t>(value)));
    }
  } else if constexpr (sizeof(I) <= 4) {
    put(iecoop::UDINT(static_cast<std::uint32_t>(value)));
  } else {
    put(iecoop::ULINT(static_cast<std::uint64_t>(value)));
  }
}

/// TIME in milliseconds, with its unit: `1500ms`.
inline void put(iecoop::TIME value) noexcept {
  put(value.count());
  put("ms");
}

/// REAL with three decimals, rounded, for magnitudes below 4,000,000 (the examples only print
/// small values that are exact in binary, so host and target agree digit for digit).
/// Formatting floats through printf or std::to_chars would link far more code than the
/// examples themselves; a 64-bit conversion would bring libgcc's double arithmetic.
inline void put(iecoop::REAL value) noexcept {
  const float x = value.value();
  const float magnitude = x < 0.0F ? -x : x;
  const auto thousandths = static_cast<std::uint32_t>(magnitude * 1000.0F + 0.5F);
  if (x < 0.0F) put("-");
  put(thousandths / 1000U);
  const auto fraction = static_cast<unsigned>(thousandths % 1000U);
  const char decimals[4] = {'.', static_cast<char>('0' + fraction / 100U),
                            static_cast<char>('0' + fraction / 10U % 10U), static_cast<char>('0' + fraction % 10U)};
  put(std::string_view(decimals, sizeof decimals));
}

/// One line: the parts one after the other, then a newline.
template <class... Parts>
void print_line(const Parts&... parts) noexcept {
  (put(parts), ...);
  put("\n");
}

}  // namespace firmware
