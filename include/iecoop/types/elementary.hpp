// SPDX-License-Identifier: MIT
// iecoop/types/elementary.hpp — the IEC 61131-3 elementary types BOOL, SINT..LINT, USINT..ULINT,
// BYTE..LWORD, REAL and LREAL, with PLC semantics in C++.
//
// * Every variable starts at 0 / FALSE, as on a PLC.
// * Integer arithmetic is CODESYS's: an operation computes its result in the registers of
//   the target — at least 32 bits, 64 on a 64-bit target — and the result is cut to the
//   variable's width only when it is assigned (see intermediate<T>). So `wVar1 + 1 = wVar2`
//   is FALSE for wVar1 = 65535, wVar2 = 0, while `wVar3 := wVar1 + 1;` stores 0. Nothing is
//   undefined behaviour: the registers wrap too. Division and MOD by zero go to the fault
//   path (see <iecoop/fault.hpp>) and yield 0.
// * Conversions follow IEC's implicit-conversion rules: widening (INT -> DINT, USINT -> INT,
//   BYTE -> WORD, INT -> REAL) is implicit; narrowing or a change of signedness needs an
//   explicit conversion (DINT_TO_INT, static_cast<INT>(d)), which keeps the low bytes.
// * A C++ integer constant converts implicitly if it fits the type; whether it fits is
//   checked at compile time (INT x = 70000; does not compile).
// * A comparison yields a BOOL, as in ST, so `b := x = 1 OR x = 3;` is `b = x == 1 | x == 3;`.
#pragma once

// The types, one header each: BOOL, the integers and bit strings with their intermediate
// results, REAL and LREAL.
#include <iecoop/types/bool.hpp>
#include <iecoop/types/integer.hpp>
#include <iecoop/types/intermediate.hpp>
#include <iecoop/types/real.hpp>

#include <iecoop/detail/push_macros.hpp>

namespace iecoop {

// ---------------------------------------------------------------------------------------
// The IEC generic types (ANY_INT, ANY_BIT, ...) as concepts.

/// SINT..LINT, USINT..ULINT (IEC ANY_INT).
template <class T>
concept AnyInt = detail::is_integer<T>::value && T::kind != integer_kind::bit_string;
/// BOOL, BYTE, WORD, DWORD, LWORD (IEC ANY_BIT).
template <class T>
concept AnyBit = std::is_same_v<T, BOOL> || (detail::is_integer<T>::value && T::kind == integer_kind::bit_string);
/// REAL, LREAL (IEC ANY_REAL).
template <class T>
concept AnyReal = detail::is_real<T>::value;
/// Any IEC integer or bit-string type (what iecoop::integer<> models).
template <class T>
concept AnyInteger = detail::is_integer<T>::value;
/// ANY_INT or ANY_REAL (IEC ANY_NUM).
template <class T>
concept AnyNum = AnyInt<T> || AnyReal<T>;
/// An intermediate result of integer arithmetic (intermediate<T>).
template <class T>
concept Intermediate = detail::is_intermediate<T>::value;

}  // namespace iecoop

#include <iecoop/detail/pop_macros.hpp>
