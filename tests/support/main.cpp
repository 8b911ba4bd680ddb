// The doctest runner for iecoop's unit tests.
//
// CTest runs every test case on its own (`--test-case=<name>`). A filter that matches no
// test case passes in doctest, so a name CTest cannot carry whole (it splits names at ';')
// would never run and never fail. This runner fails such a run instead.
#define DOCTEST_CONFIG_IMPLEMENT
#include <doctest/doctest.h>

#include <cstdio>
#include <string_view>

namespace {

int cases_matched = -1;  // test cases that passed the filters; -1: no run was reported

struct count_matches : doctest::IReporter {
  explicit count_matches(const doctest::ContextOptions&) {}
  void report_query(const doctest::QueryData&) override {}
  void test_run_start() override {}
  void test_run_end(const doctest::TestRunStats& stats) override {
    cases_matched = static_cast<int>(stats.numTestCasesPassingFilters);
  }
  void test_case_start(const doctest::TestCaseData&) override {}
  void test_case_reenter(const doctest::TestCaseData&) override {}
  void test_case_end(const doctest::CurrentTestCaseStats&) override {}
  void test_case_exception(const doctest::TestCaseException&) override {}
  void subcase_start(const doctest::SubcaseSignature&) override {}
  void subcase_end() override {}
  void log_assert(const doctest::AssertData&) override {}
  void log_message(const doctest::MessageData&) override {}
  void test_case_skipped(const doctest::TestCaseData&) override {}
};

}  // namespace

DOCTEST_REGISTER_LISTENER("iecoop_count_matches", 0, count_matches);

int main(int argc, char** argv) {
  doctest::Context context(argc, argv);
  const int result = context.run();
  if (context.shouldExit()) return result;
  bool filtered = false;
  for (int i = 1; i < argc; ++i) {
    const std::string_view arg = argv[i];
    filtered = filtered || arg.starts_with("--test-case=") || arg.starts_with("-tc=");
  }
  if (filtered && cases_matched == 0) {
    std::fputs(
        "iecoop: no test case matches the --test-case filter, so nothing was tested; CTest "
        "splits test names at ';' — name the test case without ';'\n",
        stderr);
    return 1;
  }
  return result;
}
