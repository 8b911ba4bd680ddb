// SPDX-License-Identifier: MIT
// iecoop/pou/program.hpp — PROGRAM: a block with exactly one instance, whose state persists
// between calls, callable from other POUs by name with `:=` inputs and `=>` outputs, and
// assigned to tasks by the scheduler.
//
//     // PROGRAM PRG_Sum  VAR_INPUT a, b : INT; END_VAR  VAR_OUTPUT sum : INT; END_VAR
//     struct PRG_Sum : iecoop::program<PRG_Sum> {
//       INT a; INT b; INT sum;
//       using VAR_INPUT = iecoop::pins<&PRG_Sum::a, &PRG_Sum::b>;
//       using VAR_OUTPUT = iecoop::pins<&PRG_Sum::sum>;
//       void body() { sum = a + b; }
//     };
//     PRG_Sum::instance()("a"_ = 1, "b"_ = 2, "sum"_ >> result);   // ST: PRG_Sum(a := 1, b := 2, sum => result);
#pragma once

#include <iecoop/config.hpp>
#include <iecoop/detail/single_instance.hpp>
#include <iecoop/fault.hpp>
#include <iecoop/pou/function_block.hpp>

#include <iecoop/detail/push_macros.hpp>

namespace iecoop {

/**
 * The base of a PROGRAM `Self` (CRTP): a function block of which one instance lives at a
 * time. Declare that instance once (a global, a member of your application, or let an
 * iecoop::application own it) and reach it from anywhere as `Self::instance()`
 * (`Self::exists()` tells whether it lives). Constructing a second instance while the first
 * lives reports fault_kind::duplicate_program; copies (made by an online change) do not
 * count. Without an instance, instance() reports fault_kind::invalid_value and returns a
 * scratch instance.
 */
template <class Self>
class program : public function_block<Self>, public detail::single_instance<Self, fault_kind::duplicate_program> {
 public:
  /// Marks a PROGRAM (for diagnostics that say "PROGRAM", not "FUNCTION_BLOCK").
  using iecoop_program = void;
};

}  // namespace iecoop

#include <iecoop/detail/pop_macros.hpp>
