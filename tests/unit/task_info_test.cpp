// Task information inside blocks (<iecoop/runtime/task_info.hpp>): current_task() and
// TwinCAT's F_GetTaskInfo() / GETCURTASKINDEXEX() read the task whose cycle runs the code —
// through the scheduler in simulated time, the test kit's two drivers and the real-time
// runner — and a defined "no task" outside a cycle. Every expected value is worked out by hand
// in the comment beside it.
#include "iecoop_test.hpp"

#include <iecoop/runtime/realtime.hpp>

#include <atomic>
#include <cstdint>
#include <string>
#include <vector>

using namespace iecoop;

namespace {

// What one call of a block saw of its task.
struct seen_task {
  std::string name;
  std::int32_t index;
  LTIME interval;
  std::uint64_t cycle;
  bool first;
  LTIME start;
  LTIME clock;  // cycle_clock::now() at the call
  LTIME release;
  LTIME last_exec;
  bool overran;
  // TwinCAT's view of the same
  std::string twincat_name;
  std::int32_t twincat_index;
  std::uint32_t cycle_time;  // 100 ns
  std::uint32_t cycle_count;
  std::uint32_t last_exec_time;  // 100 ns
  bool first_cycle;
  bool exceeded;
};

std::vector<seen_task> calls;  // every probe's calls, in call order

seen_task look() {
  const task_info& t = current_task();
  const PlcTaskSystemInfo info = F_GetTaskInfo();
  return seen_task{t.name(),
                   t.index(),
                   t.interval(),
                   t.cycle_number(),
                   t.first_cycle(),
                   t.cycle_start(),
                   cycle_clock::now(),
                   t.release_time(),
                   t.last_exec_time(),
                   t.overran(),
                   std::string(info.TaskName.view()),
                   static_cast<std::int32_t>(GETCURTASKINDEXEX()),
                   static_cast<std::uint32_t>(info.CycleTime),
                   static_cast<std::uint32_t>(info.CycleCount),
                   static_cast<std::uint32_t>(info.LastExecTime),
                   static_cast<bool>(info.FirstCycle),
                   static_cast<bool>(info.CycleTimeExceeded)};
}

// FUNCTION_BLOCK FB_Probe: notes what it sees of its task on every call.
struct FB_Probe : function_block<FB_Probe> {
  void body() { calls.push_back(look()); }
};

// One probe instance, called from the programs of two tasks.
struct GVL_Shared : global_variables<GVL_Shared> {
  FB_Probe fbShared;
};

struct FAST_PRG : program<FAST_PRG> {
  void body() { GVL_Shared::instance().fbShared(); }
};
struct SLOW_PRG : program<SLOW_PRG> {
  void body() { GVL_Shared::instance().fbShared(); }
};

// A program that no task calls (an ordinary variable of the caller) and the two programs of
// one task, the first calling it.
struct HELPER_PRG : program<HELPER_PRG> {
  FB_Probe fbProbe;
  void body() { fbProbe(); }
};
struct FIRST_PRG : program<FIRST_PRG> {
  HELPER_PRG helper;
  void body() { helper(); }
};
struct SECOND_PRG : program<SECOND_PRG> {
  FB_Probe fbProbe;
  void body() { fbProbe(); }
};

// A program that reads the current task while it is constructed (at start(), where FB_Init
// runs: outside any cycle).
std::int32_t index_at_init = 99;
std::int32_t twincat_index_at_init = 99;
struct INIT_PRG : program<INIT_PRG> {
  FB_Probe fbProbe;
  INIT_PRG() {
    index_at_init = current_task().index();
    twincat_index_at_init = static_cast<std::int32_t>(GETCURTASKINDEXEX());
  }
  void body() { fbProbe(); }
};

BOOL bTrigger;  // the event variable
struct EVENT_PRG : program<EVENT_PRG> {
  FB_Probe fbProbe;
  void body() { fbProbe(); }
};

LTIME ms(std::uint64_t n) { return LTIME::from_ticks(n * 1000000U); }

std::vector<seen_task> of(const std::string& task) {
  std::vector<seen_task> r;
  for (const seen_task& s : calls) {
    if (s.name == task) r.push_back(s);
  }
  return r;
}

}  // namespace

TEST_SUITE("task information in blocks") {
  TEST_CASE("two tasks of different intervals: a block called from both sees each in its turn") {
    application plc{task<FAST_PRG>{"Fast", cyclic{"T#2ms"_iec}, 0}, task<SLOW_PRG>{"Slow", cyclic{"T#10ms"_iec}, 5},
                    globals<GVL_Shared>{}};
    plc.start();
    calls.clear();
    plc.run_for("T#20ms"_iec);
    // Fast at 0, 2, .. 18 ms (10 cycles); Slow at 0 and 10 ms, each after Fast's cycle of the
    // same instant (priority 0 before 5): F S F F F F F S F F F F.
    REQUIRE(calls.size() == 12);
    std::string order;
    for (const seen_task& s : calls) order += s.name[0];
    CHECK(order == "FSFFFFFSFFFF");

    const std::vector<seen_task> fast = of("Fast");
    REQUIRE(fast.size() == 10);
    for (std::size_t i = 0; i < fast.size(); ++i) {
      CAPTURE(i);
      CHECK(fast[i].index == 0);
      CHECK(fast[i].twincat_index == 1);
      CHECK(fast[i].interval == ms(2));
      CHECK(fast[i].cycle_time == 20000U);  // T#2ms in 100 ns
      CHECK(fast[i].cycle == i + 1);
      CHECK(fast[i].cycle_count == i + 1);
      CHECK(fast[i].first == (i == 0));
      CHECK(fast[i].first_cycle == (i == 0));
      CHECK(fast[i].start == ms(2 * i));
      CHECK(fast[i].clock == ms(2 * i));
      CHECK(fast[i].twincat_name == "Fast");
      CHECK_FALSE(fast[i].overran);
    }
    const std::vector<seen_task> slow = of("Slow");
    REQUIRE(slow.size() == 2);
    CHECK(slow[0].index == 1);
    CHECK(slow[0].twincat_index == 2);
    CHECK(slow[0].interval == ms(10));
    CHECK(slow[0].cycle_time == 100000U);
    CHECK(slow[0].cycle == 1);
    CHECK(slow[0].first);
    CHECK(slow[1].cycle == 2);
    CHECK_FALSE(slow[1].first);
    CHECK(slow[1].start == ms(10));
    CHECK(slow[1].twincat_name == "Slow");
  }

  TEST_CASE("a program that two tasks call sees each task in its turn") {
    application plc{task<SECOND_PRG>{"Fast", cyclic{"T#1ms"_iec}, 0}, task<SECOND_PRG>{"Slow", cyclic{"T#2ms"_iec}, 1}};
    plc.start();
    calls.clear();
    plc.run_for("T#4ms"_iec);
    // Fast at 0, 1, 2, 3 ms; Slow at 0 and 2 ms, after Fast.
    std::string order;
    for (const seen_task& s : calls) order += s.name[0];
    CHECK(order == "FSFFSF");
    REQUIRE(of("Slow").size() == 2);
    CHECK(of("Slow")[1].index == 1);
    CHECK(of("Slow")[1].interval == ms(2));
    CHECK(of("Slow")[1].cycle == 2U);
    CHECK(of("Fast")[3].cycle == 4U);
  }

  TEST_CASE("a nested program call and the second program of a task see the same task") {
    application plc{task<FIRST_PRG, SECOND_PRG>{"Cell", cyclic{"T#5ms"_iec}, 3}};
    plc.start();
    calls.clear();
    plc.run_for("T#10ms"_iec);
    // Two cycles (0 and 5 ms), each: HELPER_PRG's probe (called by FIRST_PRG), SECOND_PRG's.
    REQUIRE(calls.size() == 4);
    for (std::size_t i = 0; i < calls.size(); ++i) {
      CAPTURE(i);
      CHECK(calls[i].name == "Cell");
      CHECK(calls[i].index == 0);
      CHECK(calls[i].interval == ms(5));
      CHECK(calls[i].cycle == i / 2 + 1);
      CHECK(calls[i].start == ms(5 * (i / 2)));
    }
  }

  TEST_CASE("outside a task cycle: no task, in FB_Init and between runs, never a fault") {
    testing::expect_faults none;  // none may be reported
    CHECK(current_task().index() == -1);
    CHECK(std::string(current_task().name()).empty());
    CHECK(current_task().interval() == LTIME{});
    CHECK(current_task().cycle_number() == 0U);
    CHECK_FALSE(current_task().first_cycle());
    CHECK(current_task().last_exec_time() == LTIME{});
    CHECK_FALSE(current_task().overran());
    CHECK(current_task().statistics().cycles == 0U);
    CHECK(GETCURTASKINDEXEX() == 0);  // TwinCAT: 0 where no cyclic task calls (FB_init)
    const PlcTaskSystemInfo info = F_GetTaskInfo();
    CHECK(info.CycleTime == 0U);
    CHECK(info.CycleCount == 0U);
    CHECK(info.LastExecTime == 0U);
    CHECK(info.Priority == 31U);  // the lowest
    CHECK(current_task().priority() == 31U);
    CHECK_FALSE(info.FirstCycle);
    CHECK_FALSE(info.CycleTimeExceeded);
    CHECK(info.TaskName.empty());

    application plc{task<FAST_PRG>{"Fast", cyclic{"T#1ms"_iec}, 0}, task<INIT_PRG>{"Init", cyclic{"T#1ms"_iec}, 1},
                    globals<GVL_Shared>{}};
    index_at_init = twincat_index_at_init = 99;
    plc.start();
    CHECK(index_at_init == -1);
    CHECK(twincat_index_at_init == 0);
    calls.clear();
    plc.run_for("T#3ms"_iec);
    CHECK(calls.size() == 6);
    CHECK(of("Init").size() == 3);
    CHECK(of("Init").front().index == 1);
    // The cycles are over: no task again.
    CHECK(current_task().index() == -1);
    CHECK(GETCURTASKINDEXEX() == 0);
    CHECK(none.count() == 0U);
  }

  TEST_CASE("the previous cycle's execution time, in LTIME and in TwinCAT's 100 ns") {
    application plc{task<FAST_PRG>{"Fast", cyclic{"T#10ms"_iec}, 0}, globals<GVL_Shared>{}};
    // Cycle n takes (n + 1) ms: 1, 2, 3 ms.
    plc.task(0).model_execution_time([](std::uint64_t n, void*) { return ms(n + 1); });
    plc.start();
    calls.clear();
    plc.run_for("T#30ms"_iec);
    REQUIRE(calls.size() == 3);
    CHECK(calls[0].last_exec == LTIME{});  // no cycle ended yet
    CHECK(calls[0].last_exec_time == 0U);
    CHECK(calls[1].last_exec == ms(1));
    CHECK(calls[1].last_exec_time == 10000U);
    CHECK(calls[2].last_exec == ms(2));
    CHECK(calls[2].last_exec_time == 20000U);
    CHECK(plc.task(0).last_exec_time() == ms(3));  // after the run: the last cycle's
    // reset_statistics() clears the statistics, not the last execution time.
    plc.task(0).reset_statistics();
    CHECK(plc.task(0).statistics().last_cycle_time == LTIME{});
    CHECK(plc.task(0).last_exec_time() == ms(3));
  }

  TEST_CASE("a skipped release: the next cycle sees that the task overran (TwinCAT's CycleTimeExceeded)") {
    application plc{task<FAST_PRG>{"Fast", cyclic{"T#10ms"_iec}, 0}, globals<GVL_Shared>{}};
    // Cycle 0 takes 15 ms: the release at 10 ms finds it under way and is skipped. Cycle 1
    // (released at 20 ms) sees the overrun; cycles 1 and 2 take 1 ms, so cycle 2 (30 ms) does not.
    plc.task(0).model_execution_time([](std::uint64_t n, void*) { return n == 0 ? ms(15) : ms(1); });
    plc.start();
    calls.clear();
    plc.run_for("T#40ms"_iec);
    REQUIRE(calls.size() == 3);  // at 0, 20 and 30 ms
    CHECK_FALSE(calls[0].overran);
    CHECK(calls[1].overran);
    CHECK(calls[1].exceeded);
    CHECK(calls[1].start == ms(20));
    CHECK(calls[1].last_exec_time == 150000U);
    CHECK_FALSE(calls[2].overran);
    CHECK_FALSE(calls[2].exceeded);
    CHECK(plc.task(0).statistics().overruns == 1U);
  }

  TEST_CASE("a cycle that starts late: its start and its release") {
    // Fast (priority 0) takes 3 ms of every 10; Slow (priority 5), released with it at 0 and
    // 10 ms, starts when Fast's cycle ends: at 3 and 13 ms.
    application plc{task<FAST_PRG>{"Fast", cyclic{"T#10ms"_iec}, 0}, task<SLOW_PRG>{"Slow", cyclic{"T#10ms"_iec}, 5},
                    globals<GVL_Shared>{}};
    plc.task("Fast").model_execution_time(ms(3));
    plc.start();
    calls.clear();
    plc.run_for("T#20ms"_iec);
    const std::vector<seen_task> slow = of("Slow");
    REQUIRE(slow.size() == 2);
    CHECK(slow[0].release == ms(0));
    CHECK(slow[0].start == ms(3));
    CHECK(slow[0].clock == ms(3));
    CHECK(slow[1].release == ms(10));
    CHECK(slow[1].start == ms(13));
  }

  TEST_CASE("after a reset the first cycle is the first again") {
    application plc{task<FAST_PRG>{"Fast", cyclic{"T#10ms"_iec}, 0}, globals<GVL_Shared>{}};
    plc.task(0).model_execution_time(ms(2));
    plc.start();
    plc.run_for("T#30ms"_iec);
    CHECK(plc.task(0).cycle_number() == 3U);
    CHECK(plc.task(0).last_exec_time() == ms(2));
    plc.reset(reset_kind::warm);
    CHECK(plc.task(0).last_exec_time() == LTIME{});
    plc.start();
    calls.clear();
    plc.run_for("T#20ms"_iec);
    REQUIRE(calls.size() == 2);
    CHECK(calls[0].first);
    CHECK(calls[0].cycle == 1U);
    CHECK(calls[0].last_exec == LTIME{});
    CHECK_FALSE(calls[1].first);
  }

  TEST_CASE("an event task: index, no interval") {
    bTrigger = FALSE;
    application plc{task<FAST_PRG>{"Fast", cyclic{"T#1ms"_iec}, 1}, task<EVENT_PRG>{"Alarm", event{bTrigger}, 0},
                    globals<GVL_Shared>{}};
    plc.start();
    plc.run_for("T#2ms"_iec);
    calls.clear();
    bTrigger = TRUE;
    plc.run_for("T#1ms"_iec);
    const std::vector<seen_task> alarm = of("Alarm");
    REQUIRE(alarm.size() == 1);
    CHECK(alarm[0].index == 1);
    CHECK(alarm[0].twincat_index == 2);
    CHECK(alarm[0].interval == LTIME{});
    CHECK(alarm[0].cycle_time == 0U);
    CHECK(alarm[0].first);
    bTrigger = FALSE;
  }

  TEST_CASE("TwinCAT's units: 100 ns, the name's first 63 characters, times stop at 16#FFFFFFFF") {
    CHECK(iecoop::detail::hundreds_of_ns(LTIME::from_ticks(150000)) == 1500U);  // LTIME#150us
    CHECK(iecoop::detail::hundreds_of_ns(LTIME::from_ticks(199)) == 1U);        // 199 ns: whole 100s
    CHECK(iecoop::detail::hundreds_of_ns(ms(429496)) == 4294960000U);
    CHECK(iecoop::detail::hundreds_of_ns(ms(429497)) == 0xFFFFFFFFU);  // past 429.4967295 s
    CHECK(iecoop::detail::hundreds_of_ns(LTIME::max()) == 0xFFFFFFFFU);

    application plc{
        task<FAST_PRG>{"A_task_name_of_seventy_characters_which_is_longer_than_TwinCAT_allows_", cyclic{"T#1h"_iec}, 0},
        globals<GVL_Shared>{}};
    plc.start();
    calls.clear();
    plc.run_for("T#1ms"_iec);
    REQUIRE(calls.size() == 1);
    CHECK(calls[0].cycle_time == 0xFFFFFFFFU);  // T#1h is 36,000,000,000 x 100 ns
    CHECK(calls[0].interval == "LTIME#1h"_iec);
    CHECK(calls[0].twincat_name == "A_task_name_of_seventy_characters_which_is_longer_than_TwinCAT_");
    CHECK(calls[0].name.size() == 70U);  // not shortened
  }
}

namespace {
// A scheduler's Cycles of its own (no application): each cycle notes what current_task() is,
// the end of a cycle notes it too (outside the programs: no task).
struct noting_cycles {
  std::vector<std::string>* log;
  void begin_cycle(std::size_t task, LTIME now) {
    const task_info& t = current_task();
    log->push_back(std::string(t.name()) + ":" + std::to_string(t.index()) + "/" + std::to_string(task) + "@" +
                   std::to_string(now.count() / 1000000U) + "#" + std::to_string(t.cycle_number()));
  }
  void end_cycle(std::size_t /*task*/, LTIME /*now*/) {
    log->push_back("end:" + std::to_string(current_task().index()));
  }
};

// A cycle observer notes the task whose cycle it observes.
std::string observed;
struct noting_observer : cycle_observer {
  noting_observer()
      : cycle_observer([](cycle_observer&, LTIME, std::uint64_t) { observed += current_task().name(); },
                       [](cycle_observer&, LTIME, std::uint64_t) { observed += current_task().name()[0]; }) {}
};
}  // namespace

TEST_SUITE("task information in blocks: the scheduler alone") {
  TEST_CASE("the scheduler makes the task of each cycle current, for its work and no longer") {
    std::vector<std::string> log;
    task_settings fast{};
    fast.name = "Fast";
    fast.interval = ms(2);
    fast.priority = 0;
    task_settings slow{};
    slow.name = "Slow";
    slow.interval = ms(3);
    slow.priority = 1;
    scheduler<2, noting_cycles> s{{fast, slow}, &log};
    s.start();
    s.run_until(ms(4));
    // Fast at 0 and 2 ms, Slow at 0 and 3 ms (after Fast at 0); each cycle takes no time.
    const std::vector<std::string> expected{"Fast:0/0@0#1", "end:-1", "Slow:1/1@0#1", "end:-1",
                                            "Fast:0/0@2#2", "end:-1", "Slow:1/1@3#2", "end:-1"};
    CHECK(log == expected);
    CHECK(current_task().index() == -1);
  }

  TEST_CASE("a task's cycle observers see their task, before and after the programs") {
    application plc{task<FAST_PRG>{"Fast", cyclic{"T#1ms"_iec}, 0}, task<SLOW_PRG>{"Slow", cyclic{"T#2ms"_iec}, 1},
                    globals<GVL_Shared>{}};
    noting_observer on_fast, on_slow;
    plc.task("Fast").attach(on_fast);
    plc.task("Slow").attach(on_slow);
    plc.start();
    observed.clear();
    plc.run_for("T#2ms"_iec);
    // Fast at 0 and 1 ms, Slow at 0: each observer's `before` notes the initial, `notify` the name.
    CHECK(observed == "FFastSSlowFFast");
  }
}

namespace {
inline auto make_two_tasks() {
  return application{task<FAST_PRG>{"Fast", cyclic{"T#1ms"_iec}, 0}, task<SLOW_PRG>{"Slow", cyclic{"T#5ms"_iec}, 2},
                     globals<GVL_Shared>{}};
}
struct TwoTasksTest : testing::plc<make_two_tasks> {};

struct I_Nothing : interface_base<I_Nothing> {
  virtual void Do() = 0;
};
struct BROKEN_PRG : program<BROKEN_PRG> {
  itf<I_Nothing> ipNothing;  // never assigned
  void body() { ipNothing->Do(); }
};
inline auto make_broken() { return application{task<BROKEN_PRG>{"Broken", cyclic{"T#1ms"_iec}, 0}}; }
}  // namespace

TEST_SUITE("task information in blocks: the test kit") {
  TEST_CASE("testing::cycles gives the block a task of the cycle time") {
    FB_Probe fbProbe;
    testing::cycles run{fbProbe, "T#20ms"_iec};
    calls.clear();
    run.step(3);
    REQUIRE(calls.size() == 3);
    for (std::size_t i = 0; i < calls.size(); ++i) {
      CAPTURE(i);
      CHECK(calls[i].name == "testing::cycles");
      CHECK(calls[i].index == 0);
      CHECK(calls[i].twincat_index == 1);
      CHECK(calls[i].interval == ms(20));
      CHECK(calls[i].cycle_time == 200000U);
      CHECK(calls[i].cycle == i + 1);
      CHECK(calls[i].first == (i == 0));
      CHECK(calls[i].start == ms(20 * i));
      CHECK(calls[i].clock == ms(20 * i));
      CHECK(calls[i].last_exec == LTIME{});  // the kit's cycles take no time
      CHECK_FALSE(calls[i].overran);
    }
    CHECK(run.task().cycle_number() == 3U);
    CHECK(run.task().statistics().cycles == 3U);
    CHECK(current_task().index() == -1);  // between steps: no task

    run.set_task_name("PlcTask");
    run.set_cycle_time("T#5ms"_iec);
    calls.clear();
    run.step();
    REQUIRE(calls.size() == 1);
    CHECK(calls[0].twincat_name == "PlcTask");
    CHECK(calls[0].interval == ms(5));
    CHECK(calls[0].cycle == 4U);
    CHECK(calls[0].start == ms(60));
  }

  TEST_CASE_FIXTURE(TwoTasksTest, "testing::plc: each task's block sees its task, in simulated time") {
    calls.clear();
    advance("T#10ms"_iec);
    // Fast at 0..9 ms, Slow at 0 and 5 ms.
    CHECK(of("Fast").size() == 10);
    REQUIRE(of("Slow").size() == 2);
    CHECK(of("Slow")[1].interval == ms(5));
    CHECK(of("Slow")[1].index == 1);
    CHECK(of("Slow")[1].cycle == 2U);
    CHECK(of("Slow")[1].start == ms(5));
    CHECK(of("Fast")[9].cycle == 10U);
    CHECK(of("Fast")[9].start == ms(9));
  }

  TEST_CASE_FIXTURE(testing::plc<make_broken>, "a cycle the kit abandons on a fault leaves no task current") {
    testing::expect_faults faults;
    step();
    CHECK(faults.count() == 1U);
    CHECK(current_task().index() == -1);
    CHECK(GETCURTASKINDEXEX() == 0);
  }
}

namespace {
struct seen_by_realtime {
  std::uint64_t calls = 0;
  std::uint64_t wrong = 0;  // calls that saw another task than their own, or an inconsistent one
};
seen_by_realtime rt_fast, rt_slow;

void check_realtime(seen_by_realtime& seen, const char* name, std::int32_t index, LTIME interval) {
  const task_info& t = current_task();
  ++seen.calls;
  const bool right = std::string(t.name()) == name && t.index() == index && t.interval() == interval &&
                     GETCURTASKINDEXEX() == index + 1 && t.cycle_start() == cycle_clock::now() &&
                     t.first_cycle() == (t.cycle_number() == 1U) && t.cycle_start() >= t.release_time();
  if (!right) ++seen.wrong;
}
struct RT_FAST_PRG : program<RT_FAST_PRG> {
  void body() { check_realtime(rt_fast, "Fast", 0, ms(2)); }
};
struct RT_SLOW_PRG : program<RT_SLOW_PRG> {
  void body() { check_realtime(rt_slow, "Slow", 1, ms(5)); }
};
}  // namespace

TEST_SUITE("task information in blocks: the real-time runner") {
  TEST_CASE("each task's program sees its own task against the steady clock") {
    rt_fast = rt_slow = seen_by_realtime{};
    application plc{task<RT_FAST_PRG>{"Fast", cyclic{"T#2ms"_iec}, 0},
                    task<RT_SLOW_PRG>{"Slow", cyclic{"T#5ms"_iec}, 1}};
    plc.start();
    std::atomic<bool> stop{false};
    realtime_runner runner{plc};
    CHECK(runner.run(stop, "T#50ms"_iec) == run_end::time_elapsed);
    // Loose bounds: a loaded machine may omit releases.
    CHECK(rt_fast.calls >= 2U);
    CHECK(rt_slow.calls >= 2U);
    CHECK(rt_fast.wrong == 0U);
    CHECK(rt_slow.wrong == 0U);
    CHECK(plc.task("Fast").cycle_number() == rt_fast.calls);
    CHECK(plc.task("Slow").last_exec_time() == plc.task("Slow").statistics().last_cycle_time);
    CHECK(current_task().index() == -1);
  }
}
