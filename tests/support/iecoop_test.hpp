// Shared helpers for iecoop's unit tests.
#pragma once

#include <doctest/doctest.h>

#include <iecoop/iecoop.hpp>
#include <iecoop/testing.hpp>  // the test kit: readable values in failed CHECKs, faults fail the test case

#include <string>
#include <type_traits>

namespace iecoop_test {

/// Records faults instead of failing the test case, for as long as it lives (the suite's
/// older form of the kit's testing::expect_faults, with the last fault's kind and message).
class fault_recorder {
 public:
  fault_recorder() : previous_(iecoop::set_fault_handler(&record)) { current() = this; }
  ~fault_recorder() {
    iecoop::set_fault_handler(previous_);
    current() = nullptr;
  }
  fault_recorder(const fault_recorder&) = delete;
  fault_recorder& operator=(const fault_recorder&) = delete;

  int count = 0;
  iecoop::fault_kind last_kind{};
  std::string last_message;
  std::string last_pou;  // "" where the fault names none

 private:
  static fault_recorder*& current() {
    static fault_recorder* instance = nullptr;
    return instance;
  }
  static void record(const iecoop::fault_info& fault) {
    fault_recorder* self = current();
    ++self->count;
    self->last_kind = fault.kind;
    self->last_message = fault.message;
    self->last_pou = fault.pou != nullptr ? fault.pou : "";
  }

  iecoop::fault_handler previous_;
};

/// `value`, passed through a volatile so the compiler cannot fold the arithmetic done on
/// it: the operation really runs, where the sanitizers watch it.
template <class T>
T opaque(T value) {
  if constexpr (iecoop::AnyDuration<T> || iecoop::AnyDate<T>) {
    volatile typename T::rep raw = value.count();
    return T::from_ticks(raw);
  } else if constexpr (std::is_same_v<T, iecoop::BOOL>) {
    volatile bool raw = static_cast<bool>(value);
    return iecoop::BOOL(static_cast<bool>(raw));
  } else if constexpr (requires { typename T::rep; }) {
    volatile typename T::rep raw = value.value();
    return T(static_cast<typename T::rep>(raw));
  } else {
    volatile T raw = value;
    return raw;
  }
}

}  // namespace iecoop_test
