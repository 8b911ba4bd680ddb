// SPDX-License-Identifier: MIT
// iecoop/detail/any_field.hpp — a stand-in for "some field" when iecoop counts the fields of
// an aggregate. Types with converting constructor templates exclude it (see iec_string),
// because such a constructor and any_field's conversion would otherwise be ambiguous.
// IWYU pragma: private, include <iecoop/detail/reflect.hpp>
#pragma once

namespace iecoop::detail {

/// Converts to (an lvalue of) any type. Used only in unevaluated probes; the body exists
/// only so that compilers do not warn about an undefined function, and is never run.
struct any_field {
  template <class T>
  operator T&() const noexcept {  // implicit: implicit on purpose
    __builtin_trap();
  }
};

}  // namespace iecoop::detail
