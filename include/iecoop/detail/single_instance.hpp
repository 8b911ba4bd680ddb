// SPDX-License-Identifier: MIT
// iecoop/detail/single_instance.hpp — a type of which one instance lives at a time, reachable
// from anywhere: PROGRAMs and global variable lists.
// IWYU pragma: private, include <iecoop/pou/program.hpp>
#pragma once

#include <iecoop/fault.hpp>

namespace iecoop::detail {

/// How many scratch instances are under construction: while one is, no program or global
/// variable list (also one nested in it) registers as the live instance of its type.
inline int scratch_depth = 0;

/// Marks the construction of a scratch instance for its lifetime.
class scratch_scope {
 public:
  scratch_scope() noexcept { ++scratch_depth; }
  ~scratch_scope() { --scratch_depth; }
  scratch_scope(const scratch_scope&) = delete;
  scratch_scope& operator=(const scratch_scope&) = delete;
};

/**
 * The base of `Self` (CRTP) that registers the instance under construction as the one of
 * its type. Constructing a second while the first lives reports `duplicate` (with
 * `duplicate_message`) and leaves the first registered; copies (made by an online change)
 * are not registered. Without an instance, instance() reports fault_kind::invalid_value and
 * returns a scratch instance, which is never registered.
 */
template <class Self, fault_kind Duplicate>
class single_instance {
 public:
  /// The live instance (or, reporting a fault, a scratch one).
  static Self& instance() {
    if (live_ == nullptr) {
      fault(fault_kind::invalid_value,
            "used before its instance exists (a PROGRAM or global variable list); a scratch instance stands in");
      return scratch();
    }
    return *live_;
  }
  /// TRUE while an instance lives.
  static bool exists() noexcept { return live_ != nullptr; }

  // Public, so that a program or list stays an aggregate (`PLC_PRG p{};`).
  single_instance() {
    if (scratch_depth > 0) return;
    if (live_ != nullptr) {
      fault(Duplicate, "a PROGRAM or global variable list has exactly one instance; this one is not registered");
      return;
    }
    // The destructor takes the registration back; GCC 12 at -O3 does not see that for an
    // instance that is a local variable (an application in a function) and warns.
#if defined(__GNUC__) && !defined(__clang__) && __GNUC__ >= 12
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wdangling-pointer"
#endif
    live_ = static_cast<Self*>(this);
#if defined(__GNUC__) && !defined(__clang__) && __GNUC__ >= 12
#pragma GCC diagnostic pop
#endif
  }
  single_instance(const single_instance&) noexcept {}  // a copy is not the instance
  single_instance& operator=(const single_instance&) noexcept { return *this; }
  ~single_instance() {
    if (live_ == static_cast<Self*>(this)) live_ = nullptr;
  }

 private:
  static Self& scratch() {
    static Self& instance = []() -> Self& {
      scratch_scope making;
      static Self made;
      return made;
    }();
    return instance;
  }
  static inline Self* live_ = nullptr;
};

}  // namespace iecoop::detail
