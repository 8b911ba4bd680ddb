// SPDX-License-Identifier: MIT
// iecoop/detail/diagnostics.hpp — helpers that turn misuse into readable compile errors.
// IWYU pragma: private, include <iecoop/iecoop.hpp>
#pragma once

namespace iecoop::detail {

/// Never defined and not constexpr: reaching a call to it during constant evaluation (in a
/// consteval function, for instance) stops compilation, and compilers print the call's
/// line, so the message passed here is what the user reads. Write it as
/// "iecoop: <rule>; <fix>".
void compile_error(const char* message);

/// false, but only once T is known: for static_assert in templates that must not be used.
template <class...>
inline constexpr bool dependent_false = false;

}  // namespace iecoop::detail
