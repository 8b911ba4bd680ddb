// SPDX-License-Identifier: MIT
// iecoop/program.hpp — PROGRAM: a block with exactly one instance, whose state persists
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
#include <iecoop/fault.hpp>
#include <iecoop/function_block.hpp>

#include <iecoop/detail/push_macros.hpp>

namespace iecoop {

/**
 * The base of a PROGRAM `Self` (CRTP): a function block of which one instance lives at a
 * time. Declare that instance once (a global, or a member of your application) and reach it
 * from anywhere as `Self::instance()`. Constructing a second instance while the first lives
 * reports fault_kind::duplicate_program; copies (made by an online change) do not count.
 */
template <class Self>
class program : public function_block<Self> {
 public:
  /// The live instance. Without one, reports fault_kind::invalid_value and returns a scratch
  /// instance (which never becomes the live one).
  static Self& instance() {
    if (live_ == nullptr) {
      fault(fault_kind::invalid_value, "PROGRAM used before its instance was declared; a scratch instance stands in");
      return scratch();
    }
    return *live_;
  }
  /// TRUE while an instance lives.
  static bool exists() noexcept { return live_ != nullptr; }

  program() {
    if (making_scratch_) return;
    if (live_ != nullptr) {
      fault(fault_kind::duplicate_program, "a PROGRAM has exactly one instance; this one is not registered");
      return;
    }
    live_ = static_cast<Self*>(this);
  }
  program(const program& other) : function_block<Self>(other) {}  // a copy is not the instance
  program& operator=(const program&) = default;
  ~program() {
    if (live_ == static_cast<Self*>(this)) live_ = nullptr;
  }

 private:
  static Self& scratch() {
    making_scratch_ = true;
    static Self instance;
    making_scratch_ = false;
    return instance;
  }
  static inline Self* live_ = nullptr;
  static inline bool making_scratch_ = false;
};

}  // namespace iecoop

#include <iecoop/detail/pop_macros.hpp>
