// Every IEC type in every position starts at ST's initial value, never undefined (issue 35):
// run under valgrind's memcheck (CTest `initial_values.memcheck`, `valgrind --error-exitcode=1`),
// where every value is branched on, so one that C++ left undefined is reported ("Conditional
// jump or move depends on uninitialised value"); and on its own, where it checks each value.
//
// `--forgotten` reads what iecoop cannot start: a C++ enum member without an initial value in
// a class that iecoop never sees (what iecoop-check's `uninitialised` reports). memcheck must
// report it (CTest `initial_values.memcheck_detects`): the check above is no check otherwise.
#include "initial_values_cases.hpp"

#include <cstdio>
#include <cstring>

namespace {

struct counter {
  int checked = 0;
  int wrong = 0;
  void operator()(const char* what, bool ok) {
    ++checked;
    if (!ok) {  // the branch memcheck checks
      ++wrong;
      std::printf("not ST's initial value: %s\n", what);
    }
  }
};

struct forgotten {
  initial_values::E_Five e;  // no initial value: undefined in C++
  iecoop::INT i;
};

[[gnu::noinline]] int read_forgotten() {
  forgotten f;
  asm volatile("" : : "r"(&f) : "memory");  // the compiler does not know what f holds
  return f.e == initial_values::E_Five::a ? 0 : 1;
}

}  // namespace

int main(int argc, char** argv) {
  if (argc > 1 && std::strcmp(argv[1], "--forgotten") == 0) {
    initial_values::fill_stack_with_garbage();
    const int result = read_forgotten();
    std::printf("read a forgotten enum member: %d\n", result);
    return 0;
  }
  counter report;
  initial_values::check_all(report);
  std::printf("%d values checked, %d not at ST's initial value\n", report.checked, report.wrong);
  return report.wrong == 0 ? 0 : 1;
}
