// The faults of PROGRAMs and global variable lists as a build for size reports them (-Os, as a
// firmware is built): one short text for every PROGRAM and list, the one it is about named by
// the fault's pou. This file alone is compiled with -Os (tests/CMakeLists.txt); its types are
// its own (an anonymous namespace), so the other files' instances keep their full texts.
#include "iecoop_test.hpp"

#if !defined(__OPTIMIZE_SIZE__)
#error "single_instance_size_build_test.cpp is compiled with -Os (tests/CMakeLists.txt)"
#endif

using namespace iecoop;

namespace {

struct seen_fault {
  fault_kind kind{};
  std::string message, task, pou;
};
std::vector<seen_fault> seen;
void record(const fault_info& f) {
  seen.push_back({f.kind, f.message, f.task != nullptr ? f.task : "", f.pou != nullptr ? f.pou : ""});
}
struct recording {
  recording() : previous(set_fault_handler(&record)) { seen.clear(); }
  ~recording() { set_fault_handler(previous); }
  recording(const recording&) = delete;
  recording& operator=(const recording&) = delete;
  fault_handler previous;
};

// VAR_GLOBAL  iCount : INT;  END_VAR
struct GVL_Small : global_variables<GVL_Small> {
  INT iCount;
};
// A program no task calls.
struct SPARE_PRG : program<SPARE_PRG> {
  INT n;
  void body() { n = n + 1; }
};
// A program that reaches SPARE_PRG by its name during its cycle.
struct CALLER_PRG : program<CALLER_PRG> {
  void body() { SPARE_PRG::instance()(); }
};

}  // namespace

TEST_SUITE("single instance faults, built for size") {
  TEST_CASE("a program in no task, a list in no application: one text each, the pou names it") {
    const recording faults;
    (void)SPARE_PRG::instance();
    (void)GVL_Small::instance();
    REQUIRE(seen.size() == 2);
    CHECK(seen[0].kind == fault_kind::invalid_value);
    CHECK(seen[0].message == "PROGRAM (the pou) in no task; name it in a task<...>; a scratch instance stands in");
    CHECK(seen[0].pou == "SPARE_PRG");
    CHECK(seen[0].task.empty());
    CHECK(seen[1].message ==
          "global variable list (the pou) in no application; add globals<...>; a scratch instance stands in");
    CHECK(seen[1].pou == "GVL_Small");
  }

  TEST_CASE("a second instance and a stopped application: the pou names the program") {
    const recording faults;
    {
      application plc{task<SPARE_PRG>{"Main", cyclic{"T#10ms"_iec}, 1}, globals<GVL_Small>{}};
      (void)SPARE_PRG::instance();  // before start()
      plc.start();
      SPARE_PRG second;  // the application owns the one
      plc.stop();
    }
    REQUIRE(seen.size() == 2);
    CHECK(seen[0].kind == fault_kind::invalid_value);
    CHECK(seen[0].message ==
          "the pou is used while its application is stopped; start() constructs it; a scratch instance stands in");
    CHECK(seen[0].pou == "SPARE_PRG");
    CHECK(seen[1].kind == fault_kind::duplicate_program);
    CHECK(seen[1].message == "a second instance of the pou, not registered; the application owns the one");
    CHECK(seen[1].pou == "SPARE_PRG");
  }

  TEST_CASE("in a task cycle the task is the running one and the pou the program the fault is about") {
    const recording faults;
    application plc{task<CALLER_PRG>{"Main", cyclic{"T#10ms"_iec}, 1}};
    plc.start();
    plc.run_for("T#10ms"_iec);
    plc.stop();
    REQUIRE(seen.size() == 1);
    CHECK(seen[0].task == "Main");
    CHECK(seen[0].pou == "SPARE_PRG");  // not CALLER_PRG, the program running
    CHECK(seen[0].message.starts_with("PROGRAM (the pou) in no task"));
  }
}
