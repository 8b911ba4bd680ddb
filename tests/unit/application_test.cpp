// The scheduler in simulated time: release and priority order, preemption, overruns, the
// watchdog, event and freewheeling tasks, statistics, and the cycle clock. Every expected
// timeline is worked out by hand in the comment beside it.
#include "iecoop_test.hpp"

#include <iecoop/runtime/application.hpp>

#include <string>
#include <vector>

using namespace iecoop;
using iecoop_test::fault_recorder;

namespace {

std::string trace;  // one letter per program call, in call order

// PROGRAM FAST_PRG / SLOW_PRG / ALARM_PRG: each writes its letter and counts its calls.
struct FAST_PRG : program<FAST_PRG> {
  var<UDINT> nCalls;
  std::vector<LTIME> seen;  // the cycle clock each call saw
  void body() {
    trace += 'F';
    nCalls = nCalls + 1U;
    seen.push_back(cycle_clock::now());
  }
};
struct SLOW_PRG : program<SLOW_PRG> {
  var<UDINT> nCalls;
  void body() {
    trace += 'S';
    nCalls = nCalls + 1U;
  }
};
struct LOW_PRG : program<LOW_PRG> {
  void body() { trace += 'L'; }
};
struct HIGH_PRG : program<HIGH_PRG> {
  void body() { trace += 'H'; }
};

BOOL bAlarm;    // VAR_GLOBAL bAlarm : BOOL; (the event variable)
BOOL bRequest;  // set by REQUEST_PRG, the event of another task

struct ALARM_PRG : program<ALARM_PRG> {
  var<UDINT> nRuns;
  LTIME last_seen{};
  void body() {
    trace += 'A';
    nRuns = nRuns + 1U;
    last_seen = cycle_clock::now();
  }
};
struct REQUEST_PRG : program<REQUEST_PRG> {
  var<UDINT> nCalls;
  void body() {
    trace += 'R';
    nCalls = nCalls + 1U;
    bRequest = BOOL(nCalls == 3U);  // rises in the third cycle
  }
};

LTIME ms(std::uint64_t n) { return LTIME::from_ticks(n * 1000000U); }

}  // namespace

TEST_SUITE("application: release and priority order") {
  TEST_CASE("tasks due at the same instant run highest priority first") {
    application plc{task<SLOW_PRG>{"Slow", cyclic{"T#1ms"_iec}, 5}, task<FAST_PRG>{"Fast", cyclic{"T#1ms"_iec}, 1}};
    plc.start();
    trace.clear();
    plc.run_for("T#3ms"_iec);
    CHECK(trace == "FSFSFS");
  }

  TEST_CASE("tasks of equal priority due at the same instant run in configuration order") {
    application plc{task<SLOW_PRG>{"Slow", cyclic{"T#1ms"_iec}, 3}, task<FAST_PRG>{"Fast", cyclic{"T#1ms"_iec}, 3}};
    plc.start();
    trace.clear();
    plc.run_for("T#3ms"_iec);
    CHECK(trace == "SFSFSF");
  }

  TEST_CASE("each task runs at its own interval") {
    // Fast every 1 ms (priority 0), Slow every 4 ms (priority 5): over [0, 8 ms)
    // 0: F S   1: F   2: F   3: F   4: F S   5: F   6: F   7: F
    application plc{task<FAST_PRG>{"Fast", cyclic{"T#1ms"_iec}, 0}, task<SLOW_PRG>{"Slow", cyclic{"T#4ms"_iec}, 5}};
    plc.start();
    trace.clear();
    plc.run_for("T#8ms"_iec);
    CHECK(trace == "FSFFFFSFFF");
    CHECK(plc.task("Fast").statistics().cycles == 8);
    CHECK(plc.task("Slow").statistics().cycles == 2);
  }

  TEST_CASE("run_for covers a span open at its end: a 1 ms task runs ten times in 10 ms") {
    application plc{task<FAST_PRG>{"Fast", cyclic{"T#1ms"_iec}, 0}};
    plc.start();
    plc.run_for("T#10ms"_iec);
    CHECK(FAST_PRG::instance().nCalls == 10U);
    CHECK(plc.now() == ms(10));
    plc.run_for("T#1ms"_iec);
    CHECK(FAST_PRG::instance().nCalls == 11U);
    plc.run_for(LTIME{});  // an empty span runs nothing
    CHECK(FAST_PRG::instance().nCalls == 11U);
  }

  TEST_CASE("run_cycles counts base cycles: the shortest cyclic interval") {
    application plc{task<SLOW_PRG>{"Slow", cyclic{"T#10ms"_iec}, 5}, task<FAST_PRG>{"Fast", cyclic{"T#2ms"_iec}, 1}};
    CHECK(plc.base_cycle() == ms(2));
    plc.start();
    plc.run_cycles(5);
    CHECK(plc.now() == ms(10));
    CHECK(FAST_PRG::instance().nCalls == 5U);
    CHECK(SLOW_PRG::instance().nCalls == 1U);
  }

  TEST_CASE("each cycle sees the time stamp of its start on the cycle clock") {
    application plc{task<FAST_PRG>{"Fast", cyclic{"T#5ms"_iec}, 0}};
    plc.start();
    plc.run_for("T#20ms"_iec);
    CHECK(FAST_PRG::instance().seen == std::vector<LTIME>{ms(0), ms(5), ms(10), ms(15)});
  }

  TEST_CASE("the same configuration and inputs give the same run") {
    const auto run = [] {
      application plc{task<FAST_PRG>{"Fast", cyclic{"T#1ms"_iec}, 2}, task<SLOW_PRG>{"Slow", cyclic{"T#3ms"_iec}, 2},
                      task<LOW_PRG>{"Low", cyclic{"T#7ms"_iec}, 9}};
      plc.task("Low").model_execution_time(LTIME(TIME(2)));
      plc.start();
      trace.clear();
      plc.run_for("T#100ms"_iec);
      return trace;
    };
    const std::string first = run();
    CHECK(first.size() > 100);
    CHECK(run() == first);
  }

  TEST_CASE("time passes while the tasks do not run") {
    application plc{task<FAST_PRG>{"Fast", cyclic{"T#1ms"_iec}, 0}};
    plc.run_for("T#5ms"_iec);  // not started
    CHECK(plc.now() == ms(5));
    plc.start();
    plc.run_for("T#2ms"_iec);
    CHECK(FAST_PRG::instance().nCalls == 2U);
    CHECK(FAST_PRG::instance().seen.front() == ms(5));  // released when started
  }
}

TEST_SUITE("application: execution time, preemption, overruns") {
  TEST_CASE("a higher-priority task preempts a running cycle") {
    // High: every 2 ms, priority 1, 1 ms per cycle. Low: every 10 ms, priority 10, 4 ms.
    //   0-1 High | 1-2 Low (3 left) | 2-3 High | 3-4 Low (2) | 4-5 High | 5-6 Low (1) | 6-7 High | 7-8 Low ends
    // Low's code runs when its cycle starts (at 1 ms); its cycle time includes the preemption.
    application plc{task<LOW_PRG>{"Low", cyclic{"T#10ms"_iec}, 10}, task<HIGH_PRG>{"High", cyclic{"T#2ms"_iec}, 1}};
    plc.task("Low").model_execution_time(ms(4));
    plc.task("High").model_execution_time(ms(1));
    plc.start();
    trace.clear();
    plc.run_for("T#10ms"_iec);
    CHECK(trace == "HLHHHH");
    const task_statistics& low = plc.task("Low").statistics();
    CHECK(low.cycles == 1);
    CHECK(low.last_jitter == ms(1));
    CHECK(low.last_cycle_time == ms(7));
    const task_statistics& high = plc.task("High").statistics();
    CHECK(high.cycles == 5);
    CHECK(high.max_jitter == LTIME{});
    CHECK(high.max_cycle_time == ms(1));
    CHECK(high.average_cycle_time() == ms(1));
  }

  TEST_CASE("a release that finds the previous cycle running is skipped and counted") {
    // Every 2 ms, 3 ms per cycle: starts at 0, 4, 8; the releases at 2, 6, 10 are omitted.
    application plc{task<FAST_PRG>{"Fast", cyclic{"T#2ms"_iec}, 0}};
    plc.task(0).model_execution_time(ms(3));
    plc.start();
    plc.run_for("T#12ms"_iec);
    const task_statistics& s = plc.task(0).statistics();
    CHECK(FAST_PRG::instance().nCalls == 3U);
    CHECK(s.cycles == 3);
    CHECK(s.overruns == 3);
    CHECK(s.consecutive_overruns == 1);
    CHECK(s.last_cycle_time == ms(3));
    CHECK(FAST_PRG::instance().seen == std::vector<LTIME>{ms(0), ms(4), ms(8)});
  }

  TEST_CASE("a lower-priority task starts late: its jitter") {
    // Both every 4 ms; High takes 1 ms first, so Low starts 1 ms after its release.
    application plc{task<HIGH_PRG>{"High", cyclic{"T#4ms"_iec}, 0}, task<LOW_PRG>{"Low", cyclic{"T#4ms"_iec}, 1}};
    plc.task("High").model_execution_time(ms(1));
    plc.start();
    plc.run_for("T#12ms"_iec);
    CHECK(plc.task("Low").statistics().min_jitter == ms(1));
    CHECK(plc.task("Low").statistics().max_jitter == ms(1));
    CHECK(plc.task("High").statistics().max_jitter == LTIME{});
  }

  TEST_CASE("cycle time statistics: last, min, max, average, and their reset") {
    // Cycle n takes (n % 3 + 1) ms: 1, 2, 3, 1, 2, 3
    application plc{task<FAST_PRG>{"Fast", cyclic{"T#10ms"_iec}, 0}};
    plc.task(0).model_execution_time([](std::uint64_t n, void*) { return LTIME::from_ticks((n % 3 + 1) * 1000000U); });
    plc.start();
    plc.run_for("T#60ms"_iec);
    const task_statistics& s = plc.task(0).statistics();
    CHECK(s.cycles == 6);
    CHECK(s.min_cycle_time == ms(1));
    CHECK(s.max_cycle_time == ms(3));
    CHECK(s.last_cycle_time == ms(3));
    CHECK(s.average_cycle_time() == ms(2));
    plc.task(0).reset_statistics();
    CHECK(plc.task(0).statistics().cycles == 0);
    plc.run_for("T#10ms"_iec);
    CHECK(plc.task(0).statistics().cycles == 1);
    CHECK(plc.task(0).statistics().last_cycle_time == ms(1));  // cycle 6: 6 % 3 + 1
  }

  TEST_CASE("the execution-time model receives a context") {
    LTIME per_cycle = ms(2);
    application plc{task<FAST_PRG>{"Fast", cyclic{"T#10ms"_iec}, 0}};
    plc.task(0).model_execution_time([](std::uint64_t, void* c) { return *static_cast<LTIME*>(c); }, &per_cycle);
    plc.start();
    plc.run_for("T#10ms"_iec);
    CHECK(plc.task(0).statistics().last_cycle_time == ms(2));
  }
}

TEST_SUITE("application: watchdog") {
  TEST_CASE("the sensitivity-th overrun in a row is a fault and stops the application") {
    // Watchdog 2 ms, sensitivity 2; cycles take 1, 3, 1, 3, 3 ms: the third overrun is the
    // second in a row, in the cycle that starts at 40 ms and ends at 43 ms.
    application plc{task<FAST_PRG>{"Fast", cyclic{"T#10ms"_iec}, 0, watchdog{"T#2ms"_iec, 2}}};
    plc.task(0).model_execution_time(
        [](std::uint64_t n, void*) { return LTIME::from_ticks((n == 0 || n == 2 ? 1U : 3U) * 1000000U); });
    fault_recorder faults;
    plc.start();
    plc.run_for("T#43ms"_iec);
    CHECK(faults.count == 0);
    CHECK(plc.task(0).statistics().watchdog_overruns == 2);
    plc.run_for("T#1ms"_iec);
    CHECK(faults.count == 1);
    CHECK(faults.last_kind == fault_kind::watchdog);
    CHECK(plc.state() == application_state::exception);
    CHECK(plc.faulted_task() == &plc.task("Fast"));
    CHECK(plc.task(0).statistics().watchdog_overruns == 3);
    CHECK(plc.task(0).statistics().consecutive_watchdog_overruns == 2);
    // Stopped in exception: no more cycles, and start() does not help; a reset does.
    plc.run_for("T#50ms"_iec);
    CHECK(FAST_PRG::instance().nCalls == 5U);
    CHECK_FALSE(plc.start());
    plc.reset(reset_kind::warm);
    CHECK(plc.state() == application_state::halted);
    CHECK(plc.faulted_task() == nullptr);
    CHECK(plc.start());
    plc.task(0).model_execution_time(ms(1));
    plc.run_for("T#10ms"_iec);
    CHECK(FAST_PRG::instance().nCalls == 1U);  // a new instance after the reset
    CHECK(faults.count == 1);
  }

  TEST_CASE("a single cycle longer than sensitivity x watchdog time is a fault at once") {
    application plc{task<FAST_PRG>{"Fast", cyclic{"T#10ms"_iec}, 0, watchdog{"T#2ms"_iec, 3}}};
    plc.task(0).model_execution_time(ms(7));  // > 3 x 2 ms
    fault_recorder faults;
    plc.start();
    plc.run_for("T#8ms"_iec);
    CHECK(faults.count == 1);
    CHECK(plc.state() == application_state::exception);
  }

  TEST_CASE("an overrun followed by a good cycle does not count as in a row") {
    application plc{task<FAST_PRG>{"Fast", cyclic{"T#10ms"_iec}, 0, watchdog{"T#2ms"_iec, 2}}};
    plc.task(0).model_execution_time(
        [](std::uint64_t n, void*) { return LTIME::from_ticks((n % 2 == 0 ? 3U : 1U) * 1000000U); });
    fault_recorder faults;
    plc.start();
    plc.run_for("T#100ms"_iec);
    CHECK(faults.count == 0);
    CHECK(plc.task(0).statistics().watchdog_overruns == 5);
    CHECK(plc.state() == application_state::running);
  }

  TEST_CASE("sensitivity 0 counts as 1: the first overrun is a fault") {
    application plc{task<FAST_PRG>{"Fast", cyclic{"T#10ms"_iec}, 0, watchdog{"T#2ms"_iec, 0}}};
    plc.task(0).model_execution_time(ms(3));
    fault_recorder faults;
    plc.start();
    plc.run_for("T#5ms"_iec);
    CHECK(faults.count == 1);
  }

  TEST_CASE("a cycle exactly as long as the watchdog time is no overrun") {
    application plc{task<FAST_PRG>{"Fast", cyclic{"T#10ms"_iec}, 0, watchdog{"T#2ms"_iec, 1}}};
    plc.task(0).model_execution_time(ms(2));
    fault_recorder faults;
    plc.start();
    plc.run_for("T#50ms"_iec);
    CHECK(faults.count == 0);
    CHECK(plc.task(0).statistics().watchdog_overruns == 0);
  }
}

TEST_SUITE("application: event and freewheeling tasks") {
  TEST_CASE("an event task runs once per rising edge of its variable") {
    bAlarm = FALSE;
    application plc{task<FAST_PRG>{"Fast", cyclic{"T#1ms"_iec}, 5}, task<ALARM_PRG>{"Alarm", event{bAlarm}, 0}};
    plc.start();
    plc.run_for("T#5ms"_iec);
    CHECK(ALARM_PRG::instance().nRuns == 0U);
    bAlarm = TRUE;
    plc.run_for("T#5ms"_iec);
    CHECK(ALARM_PRG::instance().nRuns == 1U);
    CHECK(ALARM_PRG::instance().last_seen == ms(5));  // at the start of the run that saw the edge
    plc.run_for("T#5ms"_iec);                         // still TRUE: no new edge
    CHECK(ALARM_PRG::instance().nRuns == 1U);
    bAlarm = FALSE;
    plc.run_for("T#1ms"_iec);
    bAlarm = TRUE;
    plc.run_for("T#1ms"_iec);
    CHECK(ALARM_PRG::instance().nRuns == 2U);
    CHECK(plc.task("Alarm").statistics().cycles == 2);
    bAlarm = FALSE;
  }

  TEST_CASE("an event raised by another task's program runs in the same instant") {
    // REQUEST_PRG (every 2 ms) raises bRequest in its third cycle, at 4 ms; the event task
    // (lower priority) runs right after it, at 4 ms.
    bRequest = FALSE;
    application plc{task<REQUEST_PRG>{"Request", cyclic{"T#2ms"_iec}, 1}, task<ALARM_PRG>{"Alarm", event{bRequest}, 2}};
    plc.start();
    trace.clear();
    plc.run_for("T#10ms"_iec);
    CHECK(trace == "RRRARR");
    CHECK(ALARM_PRG::instance().last_seen == ms(4));
    CHECK(plc.task("Alarm").statistics().last_jitter == LTIME{});
    bRequest = FALSE;
  }

  TEST_CASE("an event task with a condition function") {
    application plc{task<FAST_PRG>{"Fast", cyclic{"T#1ms"_iec}, 1},
                    task<ALARM_PRG>{"Alarm", event{[] { return BOOL(FAST_PRG::instance().nCalls >= 3U); }}, 0}};
    plc.start();
    trace.clear();
    plc.run_for("T#6ms"_iec);
    // FAST's third call (at 2 ms) makes the condition TRUE; sampled after that cycle: A.
    CHECK(trace == "FFFAFFF");
  }

  TEST_CASE("an edge while the event task is still busy is an overrun") {
    bAlarm = FALSE;
    application plc{task<ALARM_PRG>{"Alarm", event{bAlarm}, 0}};
    plc.task(0).model_execution_time(ms(5));
    plc.start();
    bAlarm = TRUE;
    plc.run_for("T#1ms"_iec);
    bAlarm = FALSE;
    plc.run_for("T#1ms"_iec);
    bAlarm = TRUE;
    plc.run_for("T#10ms"_iec);
    CHECK(plc.task(0).statistics().overruns == 1);
    CHECK(ALARM_PRG::instance().nRuns == 1U);
    bAlarm = FALSE;
  }

  TEST_CASE("a task refers to the hooks its kind and watchdog need, and to no other") {
    // What a firmware image links of the freewheeling pause and the watchdog check
    // (embedded/cmake/check_task_hooks.cmake) follows from these pointers.
    constexpr task<FAST_PRG> cyclic_task{"C", cyclic{"T#1ms"_iec}, 0};
    constexpr task<FAST_PRG> guarded{"G", cyclic{"T#1ms"_iec}, 0, watchdog{"T#2ms"_iec}};
    constexpr task<FAST_PRG> free_task{"F", freewheeling{}, 31};
    constexpr task<FAST_PRG> free_guarded{"FG", freewheeling{}, 31, watchdog{"T#2ms"_iec}};
    constexpr task<FAST_PRG> event_guarded{"EG", event{bAlarm}, 1, watchdog{"T#2ms"_iec}};
    static_assert(cyclic_task.settings().hooks == nullptr);
    static_assert(task<FAST_PRG>{"E", event{bAlarm}, 1}.settings().hooks == nullptr);
    const auto pause_of = [](const task_settings& s) { return s.hooks != nullptr && s.hooks->pause != nullptr; };
    const auto watchdog_of = [](const task_settings& s) {
      return s.hooks != nullptr && s.hooks->watchdog_fault != nullptr && s.hooks->report_watchdog_fault != nullptr;
    };
    CHECK((!pause_of(guarded.settings()) && watchdog_of(guarded.settings())));
    CHECK((pause_of(free_task.settings()) && !watchdog_of(free_task.settings())));
    CHECK((pause_of(free_guarded.settings()) && watchdog_of(free_guarded.settings())));
    CHECK((!pause_of(event_guarded.settings()) && watchdog_of(event_guarded.settings())));
    // The application keeps them as the tasks made them.
    application plc{task<FAST_PRG>{"F", freewheeling{}, 31, watchdog{"T#2ms"_iec}},
                    task<SLOW_PRG>{"S", cyclic{"T#1ms"_iec}, 0}};
    CHECK(plc.task("F").settings().hooks == free_guarded.settings().hooks);
    CHECK(plc.task("S").settings().hooks == nullptr);
  }

  TEST_CASE("a freewheeling task without execution time runs every millisecond") {
    application plc{task<FAST_PRG>{"Free", freewheeling{}, 31}};
    plc.start();
    plc.run_for("T#10ms"_iec);
    CHECK(FAST_PRG::instance().nCalls == 10U);
  }

  TEST_CASE("a freewheeling task pauses after each cycle in proportion to its cycle time") {
    // 80 % maximum load, one freewheeling task: L = 40 %; pause = 2 ms x 60 / 40 = 3 ms:
    // cycles start at 0, 5, 10 ms.
    application plc{task<FAST_PRG>{"Free", freewheeling{}, 31}};
    plc.task(0).model_execution_time(ms(2));
    plc.start();
    plc.run_for("T#13ms"_iec);
    CHECK(FAST_PRG::instance().seen == std::vector<LTIME>{ms(0), ms(5), ms(10)});
    plc.set_freewheeling_load(100);  // L = 50 %: pause = 2 ms
    plc.run_for("T#20ms"_iec);
    CHECK(FAST_PRG::instance().seen.back() - FAST_PRG::instance().seen[FAST_PRG::instance().seen.size() - 2] == ms(4));
  }

  TEST_CASE("two freewheeling tasks share the freewheeling load") {
    // 80 % maximum load, two freewheeling tasks: L = 40 / 2 = 20 %; a 2 ms cycle pauses
    // 2 ms x 80 / 20 = 8 ms. A (priority 30) runs 0-2, B 2-4; A again at 10, B at 12, ...
    application plc{task<FAST_PRG>{"A", freewheeling{}, 30}, task<SLOW_PRG>{"B", freewheeling{}, 31}};
    plc.task("A").model_execution_time(ms(2));
    plc.task("B").model_execution_time(ms(2));
    plc.start();
    trace.clear();
    plc.run_for("T#25ms"_iec);
    CHECK(FAST_PRG::instance().seen == std::vector<LTIME>{ms(0), ms(10), ms(20)});
    CHECK(trace == "FSFSFS");
    CHECK(plc.task("B").statistics().max_jitter == ms(2));  // released at 0, 10 (+2), 20 (+2); started 2, 12, 22
  }

  TEST_CASE("a freewheeling task yields to cyclic tasks of higher priority") {
    application plc{task<FAST_PRG>{"Fast", cyclic{"T#1ms"_iec}, 0}, task<SLOW_PRG>{"Free", freewheeling{}, 31}};
    plc.task("Fast").model_execution_time(LTIME::from_ticks(500000));
    plc.start();
    trace.clear();
    plc.run_for("T#3ms"_iec);
    // 0: F (0.5 ms), then S; S ends at 0.5 ms, pauses 1 ms; 1: F; 1.5: S; 2: F; 2.5: S
    CHECK(trace == "FSFSFS");
  }
}

TEST_SUITE("application: tasks by name, faults") {
  TEST_CASE("tasks are found by name and index") {
    application plc{task<FAST_PRG>{"Fast", cyclic{"T#1ms"_iec}, 0},
                    task<SLOW_PRG, LOW_PRG>{"Slow", cyclic{"T#10ms"_iec}, 7}};
    CHECK(plc.task_count() == 2);
    CHECK(std::string(plc.task(1).name()) == "Slow");
    CHECK(plc.task("Slow").priority() == 7);
    CHECK(plc.task("Slow").interval() == ms(10));
    CHECK(plc.task("Slow").kind() == task_kind::cyclic);
    fault_recorder faults;
    CHECK(&plc.task("Nope") == &plc.task(0));
    CHECK(faults.count == 1);
    CHECK(faults.last_kind == fault_kind::invalid_value);
    // A name is the whole name: neither a prefix nor a longer text, nor one with a NUL inside.
    CHECK(&plc.task("Slo") == &plc.task(0));
    CHECK(&plc.task("Slowly") == &plc.task(0));
    CHECK(&plc.task(std::string_view("Slow\0", 5)) == &plc.task(0));
    CHECK(faults.count == 4);
    CHECK(&plc.task(std::string_view("Slow!", 4)) == &plc.task(1));
    CHECK(faults.count == 4);
  }

  TEST_CASE("a task calls its programs in the declared order") {
    application plc{task<SLOW_PRG, LOW_PRG, FAST_PRG>{"Main", cyclic{"T#1ms"_iec}, 0}};
    plc.start();
    trace.clear();
    plc.run_for("T#2ms"_iec);
    CHECK(trace == "SLFSLF");
  }

  TEST_CASE("a program called by two tasks has one instance") {
    application plc{task<FAST_PRG>{"A", cyclic{"T#2ms"_iec}, 0}, task<FAST_PRG>{"B", cyclic{"T#3ms"_iec}, 1}};
    plc.start();
    plc.run_for("T#6ms"_iec);
    CHECK(FAST_PRG::instance().nCalls == 5U);  // A: 0, 2, 4; B: 0, 3
  }
}

namespace {

BOOL bGo;  // raised by GO_PRG's code

struct GO_PRG : program<GO_PRG> {
  void body() {
    trace += 'G';
    bGo = TRUE;
  }
};

}  // namespace

TEST_SUITE("application: review regressions") {
  TEST_CASE("an event raised by a cycle's code preempts that cycle at once, however the run is split") {
    // GO (priority 5, 4 ms) raises bGo when its cycle starts at 0 ms; ALARM (priority 0)
    // takes the processor at 0 ms, whether the run is one span or several.
    for (int split = 0; split < 2; ++split) {
      bGo = FALSE;
      application plc{task<GO_PRG>{"Go", cyclic{"T#10ms"_iec}, 5}, task<ALARM_PRG>{"Alarm", event{bGo}, 0}};
      plc.task("Go").model_execution_time(ms(4));
      plc.start();
      trace.clear();
      if (split == 0) {
        plc.run_for(ms(10));
      } else {
        plc.run_for(ms(1));
        plc.run_for(ms(9));
      }
      CHECK(trace == "GA");
      CHECK(ALARM_PRG::instance().last_seen == ms(0));
      CHECK(plc.task("Alarm").statistics().last_jitter == LTIME{});
      CHECK(plc.task("Go").statistics().last_cycle_time == ms(4));
    }
    bGo = FALSE;
  }

  TEST_CASE("a reset forgets the event memory: a condition still TRUE fires after it") {
    bAlarm = TRUE;
    application plc{task<ALARM_PRG>{"Alarm", event{bAlarm}, 0}};
    plc.start();
    plc.run_for(ms(1));
    CHECK(ALARM_PRG::instance().nRuns == 1U);
    plc.reset(reset_kind::warm);
    plc.start();
    plc.run_for(ms(1));
    CHECK(ALARM_PRG::instance().nRuns == 1U);  // a new instance, run once by the edge after the reset
    CHECK(plc.task(0).statistics().cycles == 1);
    bAlarm = FALSE;
  }

  TEST_CASE("start on a running application changes nothing") {
    application plc{task<FAST_PRG>{"Fast", cyclic{"T#10ms"_iec}, 0}};
    plc.start();
    plc.run_for(ms(3));
    CHECK(plc.start());
    plc.run_for(ms(17));
    CHECK(FAST_PRG::instance().seen == std::vector<LTIME>{ms(0), ms(10)});
  }

  TEST_CASE("resetting the statistics does not reset the watchdog's count of overruns in a row") {
    application plc{task<FAST_PRG>{"Fast", cyclic{"T#10ms"_iec}, 0, watchdog{"T#2ms"_iec, 2}}};
    plc.task(0).model_execution_time(ms(3));
    iecoop_test::fault_recorder faults;
    plc.start();
    plc.run_for(ms(5));
    plc.task(0).reset_statistics();
    plc.run_for(ms(10));
    CHECK(faults.count == 1);
    CHECK(plc.state() == application_state::exception);
  }

  TEST_CASE("a task index out of range is a fault") {
    application plc{task<FAST_PRG>{"Fast", cyclic{"T#10ms"_iec}, 0}};
    iecoop_test::fault_recorder faults;
    CHECK(&plc.task(7) == &plc.task(0));
    CHECK(faults.count == 1);
  }
}

namespace {
// The application's type named: an alias of the entries' types, or a class of its own that
// keeps the task configuration inside (where `task` alone names the member function
// application::task, so the entry is spelled iecoop::task).
using fast_slow = application<task<FAST_PRG>, task<SLOW_PRG>>;
struct fast_slow_plc : fast_slow {
  fast_slow_plc()
      : fast_slow{iecoop::task<FAST_PRG>{"Fast", cyclic{"T#1ms"_iec}, 0},
                  iecoop::task<SLOW_PRG>{"Slow", cyclic{"T#5ms"_iec}, 1}} {}
};
template <class Plc>
void run_ten_ms(Plc& plc) {
  plc.run_for(ms(10));
}
void run_ten_ms_named(fast_slow& plc) { run_ten_ms(plc); }
}  // namespace

TEST_SUITE("application: a named application type") {
  TEST_CASE("a class derived from application is passed around like any other") {
    trace.clear();
    fast_slow_plc plc;
    REQUIRE(plc.start());
    run_ten_ms(plc);
    CHECK(plc.task("Fast").statistics().cycles == 10);
    CHECK(plc.task("Slow").statistics().cycles == 2);
    CHECK(plc.get<SLOW_PRG>().nCalls == 2U);
    CHECK(trace.substr(0, 3) == "FSF");
  }
  TEST_CASE("an alias of the entries' types names it where it is built") {
    fast_slow plc{task<FAST_PRG>{"Fast", cyclic{"T#2ms"_iec}, 0}, task<SLOW_PRG>{"Slow", cyclic{"T#5ms"_iec}, 1}};
    REQUIRE(plc.start());
    run_ten_ms_named(plc);
    CHECK(plc.task("Fast").statistics().cycles == 5);
  }
}
