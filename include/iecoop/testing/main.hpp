// SPDX-License-Identifier: MIT
// iecoop/testing/main.hpp — the test program's main(): doctest's, and a run whose
// --test-case filter matches no test case fails (CTest splits test names at ';', and a
// filter that matches nothing would pass without testing anything). Included by
// <iecoop/testing.hpp> where IECOOP_TESTING_MAIN is defined: in exactly one source file.
// IWYU pragma: private, include <iecoop/testing.hpp>
#pragma once

#define DOCTEST_CONFIG_IMPLEMENT
#include <doctest/doctest.h>

#include <cstdio>
#include <string_view>

#include <iecoop/testing/listener.hpp>

namespace iecoop::testing::detail {

inline int cases_matched = -1;  // test cases that passed the filters; -1: no run was reported

struct count_matches : quiet_listener {
  using quiet_listener::quiet_listener;
  void test_run_end(const doctest::TestRunStats& stats) override {
    cases_matched = static_cast<int>(stats.numTestCasesPassingFilters);
  }
};

}  // namespace iecoop::testing::detail

DOCTEST_REGISTER_LISTENER("iecoop_count_matches", 0, iecoop::testing::detail::count_matches);

int main(int argc, char** argv) {
  doctest::Context context(argc, argv);
  const int result = context.run();
  if (context.shouldExit()) return result;
  bool filtered = false;
  for (int i = 1; i < argc; ++i) {
    const std::string_view arg = argv[i];
    filtered = filtered || arg.starts_with("--test-case=") || arg.starts_with("-tc=");
  }
  if (filtered && iecoop::testing::detail::cases_matched == 0) {
    std::fputs(
        "iecoop: no test case matches the --test-case filter, so nothing was tested; CTest "
        "splits test names at ';': name the test case without ';'\n",
        stderr);
    return 1;
  }
  return result;
}
