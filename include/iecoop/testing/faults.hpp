// SPDX-License-Identifier: MIT
// iecoop/testing/faults.hpp — faults in unit tests: while a doctest test case runs, an iecoop
// fault (division by zero, a call through an unassigned interface, a watchdog, ...) fails that
// test case with its kind, message, task, program and simulated time, and the run goes on
// with the next case; a test that provokes a fault on purpose expects it instead:
//
//     CHECK_FAULT(plc.step(), fault_kind::division_by_zero);   // this fault, and no other
//
//     testing::expect_faults faults;      // faults are recorded here while it lives
//     plc.step();
//     CHECK(faults.count() == 1);
//     CHECK(faults.last().task == std::string_view("Fast"));
//
// A PLC stops its application on such an exception; the kit's drivers (testing::plc,
// testing::cycles) likewise run no more cycles in a test case that had an unexpected fault, so
// that a fault every cycle is reported once, not an hour of times. Outside test cases (static
// initialisation, main) faults go to the handler that was installed before (by default: print
// and abort).
//
// Most faults let the faulting operation finish with a defined result. A call through an
// unassigned interface variable cannot finish (there is no block to call): the library stops
// the program if the handler returns. In a test case the kit's handler throws
// testing::call_abandoned instead, after recording the fault; the drivers catch it and end the
// cycle there (testing::plc: the application halts, as a PLC stops on an exception), and so
// does CHECK_FAULT. (Built without exceptions, the program still stops.)
// IWYU pragma: private, include <iecoop/testing.hpp>
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <exception>
#include <string>
#include <string_view>

#include <doctest/doctest.h>

#include <iecoop/fault.hpp>
#include <iecoop/ostream.hpp>
#include <iecoop/standard/cycle_clock.hpp>
#include <iecoop/testing/listener.hpp>
#include <iecoop/types/time.hpp>

#include <iecoop/detail/push_macros.hpp>

namespace iecoop::testing {

/// A fault as a test sees it: the fault_info and the simulated time (the cycle clock) it
/// happened at.
struct fault_record {
  fault_kind kind{};
  const char* message = "";
  const char* task = nullptr;  ///< the task whose cycle was running, or nullptr
  const char* pou = nullptr;   ///< the program it was calling (a lifecycle fault: the block), or nullptr
  LTIME time{};                ///< the cycle clock then
};

/// "division by zero: integer division or MOD by zero (task Fast, program IO_PRG, at T#1s500ms)".
inline std::string describe(const fault_record& f) {
  std::string text = to_string(f.kind);
  text += ": ";
  text += f.message;
  text += " (";
  if (f.task != nullptr) {
    text += "task ";
    text += f.task;
    if (f.pou != nullptr) {
      text += ", program ";
      text += f.pou;
    }
    text += ", ";
  } else if (f.pou != nullptr) {
    text += f.pou;  // outside a cycle: the block a lifecycle fault is about
    text += ", ";
  }
  char time[max_text_length<LTIME>];
  const LTIME ms = LTIME(TIME(f.time));
  const char* end = ms == f.time ? to_text(time, TIME(f.time)) : to_text(time, f.time);
  text += "cycle clock ";
  text.append(time, static_cast<std::size_t>(end - time));
  text += ")";
  return text;
}

/// Thrown by the kit's fault handler in a test case after a fault the faulting call cannot
/// go past (a call through an unassigned interface variable), where the library would stop
/// the program; the drivers and CHECK_FAULT catch it (see above).
struct call_abandoned : std::exception {
  [[nodiscard]] const char* what() const noexcept override {
    return "iecoop: a call through an unassigned interface could not go on (the fault is reported above); "
           "call it through testing::cycles or testing::plc, or in CHECK_FAULT";
  }
};

namespace detail {

/// TRUE for a fault whose call cannot finish: the library aborts if the handler returns.
[[nodiscard]] constexpr bool abandons_call(fault_kind kind) noexcept {
  return kind == fault_kind::unassigned_interface;
}

/// Calls `f`; FALSE if a fault abandoned the call (call_abandoned), TRUE if it returned.
template <class F>
bool call_guarded(F&& f) {
#if defined(__cpp_exceptions)
  try {
    f();
  } catch (const call_abandoned&) {
    return false;
  }
#else
  f();
#endif
  return true;
}

/// After the kit's handler recorded a fault the call cannot go past: leave the call.
inline void abandon_call() {
#if defined(__cpp_exceptions)
  throw call_abandoned{};
#endif
}

}  // namespace detail

class expect_faults;

/// Where a test called the kit: a file and a line (std::source_location, which clang 14 with
/// libstdc++ 12 does not have).
struct call_site {
  const char* file = nullptr;
  unsigned line = 0;
  static constexpr call_site current(const char* file = __builtin_FILE(), unsigned line = __builtin_LINE()) noexcept {
    return {file, line};
  }
};

namespace detail {

/// The kit's state, one per process (doctest runs one test case at a time).
struct kit_state {
  expect_faults* expecting = nullptr;  // the innermost expect_faults alive
  std::uint32_t unexpected = 0;        // unexpected faults in the current test case
  fault_handler previous = nullptr;    // the handler before the kit's (restored after each case)
  bool installed = false;
  const char* file = nullptr;  // where the test called the driver that is running cycles now
  unsigned line = 0;
  const char* case_file = nullptr;  // the running test case, for a fault outside the drivers
  unsigned case_line = 0;
};
inline kit_state kit{};

/// Names the test's line that drives the cycles (step, advance, ...) for the faults they raise.
class driving_scope {
 public:
  explicit driving_scope(call_site where) noexcept : file_(kit.file), line_(kit.line) {
    if (kit.file == nullptr) {  // the outermost call is the test's own line
      kit.file = where.file;
      kit.line = where.line;
    }
  }
  driving_scope(const driving_scope&) = delete;
  driving_scope& operator=(const driving_scope&) = delete;
  ~driving_scope() {
    kit.file = file_;
    kit.line = line_;
  }

 private:
  const char* file_;
  unsigned line_;
};

inline constexpr std::uint32_t max_reported_faults = 8;  // per test case; the rest are counted

inline void kit_fault_handler(const fault_info& info);

}  // namespace detail

/**
 * Records the faults that happen while it lives, instead of failing the test case: for tests
 * that provoke faults on purpose. Keeps the first `capacity` records and counts all. Scopes
 * nest; the innermost one records.
 */
class expect_faults {
 public:
  static constexpr std::size_t capacity = 16;

  expect_faults() noexcept : outer_(detail::kit.expecting) { detail::kit.expecting = this; }
  expect_faults(const expect_faults&) = delete;
  expect_faults& operator=(const expect_faults&) = delete;
  ~expect_faults() { detail::kit.expecting = outer_; }

  /// All faults recorded.
  [[nodiscard]] std::size_t count() const noexcept { return count_; }
  /// The faults of `kind` among those kept.
  [[nodiscard]] std::size_t count(fault_kind kind) const noexcept {
    std::size_t n = 0;
    for (std::size_t i = 0; i < kept(); ++i) n += records_[i].kind == kind ? 1U : 0U;
    return n;
  }
  [[nodiscard]] bool empty() const noexcept { return count_ == 0; }
  /// The i-th fault kept (0: the first).
  [[nodiscard]] const fault_record& operator[](std::size_t i) const noexcept { return records_[i < kept() ? i : 0]; }
  /// The last fault kept (a default record if there is none).
  [[nodiscard]] const fault_record& last() const noexcept { return records_[count_ == 0 ? 0 : kept() - 1]; }
  [[nodiscard]] std::size_t kept() const noexcept { return count_ < capacity ? count_ : capacity; }

  /// TRUE if the faults recorded are all of `kind`, and there is at least one.
  [[nodiscard]] bool only(fault_kind kind) const noexcept { return count_ > 0 && count(kind) == kept(); }

  /// The faults kept, one per line, for a failure message.
  [[nodiscard]] std::string text() const {
    if (count_ == 0) return "no fault";
    std::string out;
    for (std::size_t i = 0; i < kept(); ++i) {
      if (i > 0) out += "\n";
      out += describe(records_[i]);
    }
    if (count_ > kept()) out += "\n... and " + std::to_string(count_ - kept()) + " more";
    return out;
  }

  void record(const fault_record& f) noexcept {
    if (count_ < capacity) records_[count_] = f;
    ++count_;
  }

 private:
  expect_faults* outer_;
  std::array<fault_record, capacity> records_{};
  std::size_t count_ = 0;
};

/// TRUE while the current test case had an unexpected fault (the drivers run no more cycles).
[[nodiscard]] inline bool faulted() noexcept { return detail::kit.unexpected > 0; }

namespace detail {

inline void kit_fault_handler(const fault_info& info) {
  const fault_record record{info.kind, info.message, info.task, info.pou, cycle_clock::now()};
  if (kit.expecting != nullptr) {
    kit.expecting->record(record);
    if (abandons_call(info.kind)) abandon_call();
    return;
  }
  if (!doctest::is_running_in_test) {
    (kit.previous != nullptr ? kit.previous : &default_fault_handler)(info);
    return;
  }
  ++kit.unexpected;
  if (kit.unexpected <= max_reported_faults) {
    const std::string text =
        "iecoop fault: " + describe(record) +
        (kit.unexpected == max_reported_faults ? " (further faults in this test case are counted, not shown)" : "");
    // A failed check "no iecoop fault" whose value is the fault: reporters see it as any
    // failed CHECK (doctest's JUnit reporter, for one, ignores messages).
    // At the test's line that drives the cycles, else at its test case.
    const bool driving = kit.file != nullptr;
    doctest::detail::ResultBuilder check(doctest::assertType::DT_CHECK, driving ? kit.file : kit.case_file,
                                         static_cast<int>(driving ? kit.line : kit.case_line), "no iecoop fault");
    check.setResult(doctest::detail::Result(false, doctest::String(text.c_str())));
    static_cast<void>(check.log());
    check.react();
  }
  if (abandons_call(info.kind)) abandon_call();
}

/// Installs the kit's fault handler for each test case and clears the per-case state: a
/// doctest listener (registered by <iecoop/testing.hpp>).
struct kit_listener : quiet_listener {
  using quiet_listener::quiet_listener;
  void test_case_start(const doctest::TestCaseData& data) override { begin(data); }
  void test_case_reenter(const doctest::TestCaseData& data) override { begin(data); }
  void test_case_end(const doctest::CurrentTestCaseStats& /*stats*/) override { end(); }

  static void begin(const doctest::TestCaseData& data) noexcept {
    kit.unexpected = 0;
    kit.file = nullptr;
    kit.case_file = data.m_file.c_str();
    kit.case_line = data.m_line;
    kit.expecting = nullptr;
    if (!kit.installed) {
      kit.previous = set_fault_handler(&kit_fault_handler);
      kit.installed = true;
    }
  }
  static void end() noexcept {
    if (kit.installed) {
      set_fault_handler(kit.previous);
      kit.installed = false;
    }
  }
};

}  // namespace detail
}  // namespace iecoop::testing

// Registered once per translation unit that includes the kit; doctest keeps one per name.
DOCTEST_REGISTER_LISTENER("iecoop_testing", 0, iecoop::testing::detail::kit_listener);

/// CHECK_FAULT(expression, kind): evaluating `expression` raises one or more faults, all of
/// `kind` (and they fail nothing else). REQUIRE_FAULT ends the test case if not.
#define IECOOP_FAULT_ASSERT_(assertion, expression, kind)                                                 \
  do {                                                                                                    \
    ::iecoop::testing::expect_faults raised;                                                              \
    ::iecoop::testing::detail::call_guarded([&] { static_cast<void>(expression); });                      \
    assertion(raised.only(kind), #expression << " raised " << raised.text() << "; expected "              \
                                             << std::string(::iecoop::to_string(kind)) << ", only that"); \
  } while (false)
#define IECOOP_CHECK_FAULT(expression, kind) IECOOP_FAULT_ASSERT_(DOCTEST_CHECK_MESSAGE, expression, kind)
#define IECOOP_REQUIRE_FAULT(expression, kind) IECOOP_FAULT_ASSERT_(DOCTEST_REQUIRE_MESSAGE, expression, kind)
#if !defined(IECOOP_TESTING_NO_SHORT_MACROS)
#define CHECK_FAULT(expression, kind) IECOOP_CHECK_FAULT(expression, kind)
#define REQUIRE_FAULT(expression, kind) IECOOP_REQUIRE_FAULT(expression, kind)
#endif

#include <iecoop/detail/pop_macros.hpp>
