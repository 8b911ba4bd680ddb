// SPDX-License-Identifier: MIT
// iecoop/detail/diagnostics.hpp — helpers that turn misuse into readable compile errors.
// IWYU pragma: private, include <iecoop/iecoop.hpp>
#pragma once

#include <iecoop/fault.hpp>

namespace iecoop::detail {

/// Not constexpr: reaching a call to it during constant evaluation (in a consteval
/// function, for instance) stops compilation, and compilers print the call's line, so the
/// message passed here is what the user reads. Write it as "iecoop: <rule>; <fix>".
///
/// It is defined only because Clang 14 fails to evaluate consteval constructors in
/// namespace-scope and default member initializers at compile time and calls them at run
/// time instead: there the check becomes a fault (fault_kind::invalid_value).
inline void compile_error(const char* message) { fault(fault_kind::invalid_value, message); }

/// false, but only once T is known: for static_assert in templates that must not be used.
template <class...>
inline constexpr bool dependent_false = false;

}  // namespace iecoop::detail
