// SPDX-License-Identifier: MIT
// iecoop/detail/iec_value.hpp — which types are IEC values (BOOL, the integers and their
// intermediate results, REAL, TIME, STRING, interface variables): what a variable wrapper's
// operators accept on their other side. Each type's own header says that it is one.
// IWYU pragma: private, include <iecoop/iecoop.hpp>
#pragma once

#include <type_traits>

namespace iecoop::detail {

template <class T>
struct is_iec_value : std::false_type {};

}  // namespace iecoop::detail
