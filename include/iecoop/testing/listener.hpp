// SPDX-License-Identifier: MIT
// iecoop/testing/listener.hpp — a doctest listener that does nothing: the kit's listeners
// (faults.hpp, main.hpp) derive from it and override only the events they need.
// IWYU pragma: private, include <iecoop/testing.hpp>
#pragma once

#include <doctest/doctest.h>

namespace iecoop::testing::detail {

struct quiet_listener : doctest::IReporter {
  explicit quiet_listener(const doctest::ContextOptions& /*options*/) {}
  void report_query(const doctest::QueryData& /*data*/) override {}
  void test_run_start() override {}
  void test_run_end(const doctest::TestRunStats& /*stats*/) override {}
  void test_case_start(const doctest::TestCaseData& /*data*/) override {}
  void test_case_reenter(const doctest::TestCaseData& /*data*/) override {}
  void test_case_end(const doctest::CurrentTestCaseStats& /*stats*/) override {}
  void test_case_exception(const doctest::TestCaseException& /*data*/) override {}
  void subcase_start(const doctest::SubcaseSignature& /*signature*/) override {}
  void subcase_end() override {}
  void log_assert(const doctest::AssertData& /*data*/) override {}
  void log_message(const doctest::MessageData& /*data*/) override {}
  void test_case_skipped(const doctest::TestCaseData& /*data*/) override {}
};

}  // namespace iecoop::testing::detail
