// The fault context (<iecoop/fault.hpp>): a fault names the task whose cycle runs and the
// program it calls, current_fault_context() and current_task() read the same context, and a
// cycle run from code that has its own context gives that context back. The scheduler makes
// its task's context current with one pointer, so these are checked through every way in: the
// application's cycles, the watchdog, a context of the caller's, the test kit's cycles.
#include "iecoop_test.hpp"

#include <iecoop/runtime/application.hpp>

#include <string>
#include <vector>

using namespace iecoop;

namespace {

// What a program saw of the context, and the faults it reported.
struct seen_context {
  std::string task;
  std::string pou;
  std::string current_task;  // current_task().name()
  bool cycle_task_is_current;
};
std::vector<seen_context> seen;
std::vector<seen_context> faults;  // task, pou of each fault_info ("" for nullptr)

std::string text(const char* s) { return s != nullptr ? s : ""; }

void look() {
  const fault_context c = current_fault_context();
  seen.push_back({text(c.task), text(c.pou), current_task().name(), c.cycle_task == &current_task()});
}

void record(const fault_info& f) { faults.push_back({text(f.task), text(f.pou), current_task().name(), false}); }

// PROGRAM PRG_A and PRG_B: one task calls both; each looks at its context and reports a user
// fault. PRG_C, in a second task, only looks.
struct PRG_A : program<PRG_A> {
  void body() {
    look();
    fault(fault_kind::user, "from A");
  }
};
struct PRG_B : program<PRG_B> {
  void body() {
    look();
    fault(fault_kind::user, "from B");
  }
};
struct PRG_C : program<PRG_C> {
  void body() { look(); }
};

}  // namespace

TEST_SUITE("fault context") {
  TEST_CASE("a cycle's programs see their task and their own name; outside, nothing") {
    seen.clear();
    faults.clear();
    const fault_handler previous = set_fault_handler(&record);
    {
      application plc{task<PRG_A, PRG_B>{"Main", cyclic{"T#10ms"_iec}, 1},
                      task<PRG_C>{"Side", cyclic{"T#20ms"_iec}, 2}};
      const fault_context before = current_fault_context();
      CHECK(before.task == nullptr);
      CHECK(before.pou == nullptr);
      CHECK(before.cycle_task == nullptr);
      plc.start();
      plc.run_for("T#20ms"_iec);  // 0 ms: Main, Side; 10 ms: Main
      const fault_context after = current_fault_context();
      CHECK(after.task == nullptr);
      CHECK(after.pou == nullptr);
      CHECK(after.cycle_task == nullptr);
    }
    set_fault_handler(previous);
    // Main (priority 1) before Side (priority 2) at 0 ms.
    const std::vector<std::vector<std::string>> expected_seen{{"Main", "PRG_A", "Main"},
                                                              {"Main", "PRG_B", "Main"},
                                                              {"Side", "PRG_C", "Side"},
                                                              {"Main", "PRG_A", "Main"},
                                                              {"Main", "PRG_B", "Main"}};
    REQUIRE(seen.size() == expected_seen.size());
    for (std::size_t i = 0; i < seen.size(); ++i) {
      INFO("call ", i);
      CHECK(std::vector<std::string>{seen[i].task, seen[i].pou, seen[i].current_task} == expected_seen[i]);
      CHECK(seen[i].cycle_task_is_current);
    }
    REQUIRE(faults.size() == 4);
    CHECK(faults[0].task == "Main");
    CHECK(faults[0].pou == "PRG_A");
    CHECK(faults[1].pou == "PRG_B");
    CHECK(faults[3].pou == "PRG_B");
  }

  TEST_CASE("a cycle run inside a context of the caller's gives that context back") {
    seen.clear();
    faults.clear();
    const fault_handler previous = set_fault_handler(&record);
    {
      application plc{task<PRG_C>{"Side", cyclic{"T#10ms"_iec}, 2}};
      plc.start();
      fault_context outer{"Outer", "OUTER_POU", nullptr};
      {
        const detail::fault_context_scope scope(outer);
        plc.run_for("T#10ms"_iec);
        const fault_context now = current_fault_context();
        CHECK(text(now.task) == "Outer");
        CHECK(text(now.pou) == "OUTER_POU");
        CHECK(now.cycle_task == nullptr);
        fault(fault_kind::user, "outside the cycle");
      }
      CHECK(current_fault_context().task == nullptr);
    }
    set_fault_handler(previous);
    REQUIRE(seen.size() == 1);
    CHECK(seen[0].task == "Side");
    CHECK(seen[0].pou == "PRG_C");
    REQUIRE(faults.size() == 1);
    CHECK(faults[0].task == "Outer");
    CHECK(faults[0].pou == "OUTER_POU");
    CHECK(faults[0].current_task.empty());  // current_task() outside a cycle: no task
  }

  TEST_CASE("the test kit's cycles: the body's task is current, the surrounding context stays") {
    seen.clear();
    testing::cycles kit{[] { look(); }, "T#10ms"_iec};
    kit.set_task_name("KitTask");
    kit.step(2);
    REQUIRE(seen.size() == 2);
    CHECK(seen[0].task.empty());  // the kit runs no application: no task in fault reports
    CHECK(seen[0].current_task == "KitTask");
    CHECK(seen[0].cycle_task_is_current);
    CHECK(current_fault_context().cycle_task == nullptr);
  }
}
