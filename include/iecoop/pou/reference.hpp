// SPDX-License-Identifier: MIT
// iecoop/pou/reference.hpp — REFERENCE TO: `r : REFERENCE TO INT;` is `REFERENCE_TO<INT> r;`,
// `r REF= x;` is `r.bind(x);`, `__ISVALIDREF(r)` is `is_valid_ref(r)`.
//
// A reference is what a VAR_IN_OUT is — an alias bound to a variable, read and written like
// it — so REFERENCE_TO<T> is in_out<T>: `r := 5;` writes through, `a := r;` reads through, and
// using it before it is bound is a fault (fault_kind::unbound_in_out), never an access to
// address 0.
#pragma once

#include <iecoop/config.hpp>
#include <iecoop/pou/variables.hpp>
#include <iecoop/types/elementary.hpp>

#include <iecoop/detail/push_macros.hpp>

namespace iecoop {

/// ST's `REFERENCE TO T`.
template <class T>
using REFERENCE_TO = in_out<T>;

/// ST's `__ISVALIDREF(r)`: TRUE once the reference is bound (`r REF= x`).
template <class T>
[[nodiscard]] constexpr BOOL is_valid_ref(const in_out<T>& reference) noexcept {
  return BOOL(reference.bound());
}

}  // namespace iecoop

#include <iecoop/detail/pop_macros.hpp>
