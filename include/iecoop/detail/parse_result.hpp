// SPDX-License-Identifier: MIT
// iecoop/detail/parse_result.hpp — the one shape of a parse's outcome in iecoop: the value, or
// why there is none and where the text went wrong. Literal text (parse_result<T>, with a
// parse_error) and direct addresses (address_parse, with an address_error) both use it.
// IWYU pragma: private, include <iecoop/iecoop.hpp>
#pragma once

#include <cstddef>

#include <iecoop/config.hpp>
#include <iecoop/fault.hpp>

#include <iecoop/detail/push_macros.hpp>

namespace iecoop {

/**
 * The result of parsing text as a `T`: the value, or an `Error` (an enumeration whose
 * `none` means success) and the offset in the text where it was found.
 *
 *     auto r = parse_time("T#1h30m");
 *     if (r) use(*r); else log(describe(r.error()), r.position());
 */
template <class T, class Error>
class basic_parse_result {
 public:
  constexpr basic_parse_result(T value) noexcept : value_(value) {}  // implicit: a value is a result
  constexpr basic_parse_result(Error error, std::size_t position) noexcept : error_(error), position_(position) {}

  [[nodiscard]] constexpr bool has_value() const noexcept { return error_ == Error::none; }
  explicit constexpr operator bool() const noexcept { return has_value(); }
  [[nodiscard]] constexpr Error error() const noexcept { return error_; }
  /// Offset of the first offending character (0 on success).
  [[nodiscard]] constexpr std::size_t position() const noexcept { return position_; }
  /// The value; on error reports fault_kind::invalid_value and returns T{} (and does not
  /// compile in a constant expression).
  [[nodiscard]] constexpr T value() const {
    if (!has_value()) {
      fault(fault_kind::invalid_value, "value() of a failed parse; check has_value() first");
    }
    return value_;
  }
  [[nodiscard]] constexpr T value_or(T fallback) const noexcept { return has_value() ? value_ : fallback; }
  [[nodiscard]] constexpr T operator*() const { return value(); }

 private:
  T value_{};
  Error error_ = Error::none;
  std::size_t position_ = 0;
};

}  // namespace iecoop

#include <iecoop/detail/pop_macros.hpp>
