// The real-time runner, briefly and with loose bounds: the machines that run these tests are
// shared and noisy, so only what must hold on any of them is asserted (speed and jitter
// figures belong to bench/).
#include "iecoop_test.hpp"

#include <iecoop/runtime/realtime.hpp>

#include <atomic>
#include <chrono>
#include <ctime>
#include <thread>

using namespace iecoop;

namespace {

struct TICK_PRG : program<TICK_PRG> {
  var<UDINT> nCalls;
  LTIME first{};
  LTIME last{};
  void body() {
    if (nCalls == 0U) first = cycle_clock::now();
    last = cycle_clock::now();
    nCalls = nCalls + 1U;
  }
};

BOOL bRealtimeEvent;
struct EVENT_PRG : program<EVENT_PRG> {
  var<UDINT> nRuns;
  void body() { nRuns = nRuns + 1U; }
};

}  // namespace

TEST_SUITE("realtime runner") {
  TEST_CASE("a 2 ms task runs against the steady clock for the time asked") {
    application plc{task<TICK_PRG>{"Tick", cyclic{"T#2ms"_iec}, 0}};
    plc.start();
    std::atomic<bool> stop{false};
    realtime_runner runner{plc};
    const auto wall_start = std::chrono::steady_clock::now();
    CHECK(runner.run(stop, "T#200ms"_iec) == run_end::time_elapsed);
    const auto wall = std::chrono::steady_clock::now() - wall_start;
    CHECK(wall >= std::chrono::milliseconds(200));
    CHECK(wall < std::chrono::seconds(5));
    CHECK(plc.now() >= LTIME("T#200ms"_iec));
    CHECK(plc.now() < LTIME("T#5s"_iec));
    const task_statistics& s = plc.task(0).statistics();
    // 100 releases in 200 ms; a loaded machine may omit some, none may run twice.
    CHECK(s.cycles >= 20);
    CHECK(s.cycles <= 100);
    CHECK(s.cycles + s.overruns <= 101);
    CHECK(TICK_PRG::instance().nCalls == s.cycles);
    CHECK(TICK_PRG::instance().last > TICK_PRG::instance().first);
    CHECK(s.max_jitter >= s.min_jitter);
    CHECK(s.max_cycle_time >= s.min_cycle_time);
    CHECK_FALSE(runner.fifo_active());
  }

  TEST_CASE("a stop request ends the run, the clock continues from the simulated time") {
    application plc{task<TICK_PRG>{"Tick", cyclic{"T#5ms"_iec}, 0}};
    plc.start();
    plc.run_for("T#1s"_iec);  // simulated first
    CHECK(TICK_PRG::instance().nCalls == 200U);
    std::atomic<bool> stop{false};
    std::thread stopper([&] {
      std::this_thread::sleep_for(std::chrono::milliseconds(50));
      stop = true;
    });
    realtime_runner runner{plc};
    CHECK(runner.run(stop) == run_end::stop_requested);
    stopper.join();
    CHECK(plc.now() > LTIME("T#1s"_iec));
    CHECK(TICK_PRG::instance().nCalls > 200U);
  }

  TEST_CASE("an application that is not running ends the run at once") {
    application plc{task<TICK_PRG>{"Tick", cyclic{"T#5ms"_iec}, 0}};
    std::atomic<bool> stop{false};
    realtime_runner runner{plc};
    CHECK(runner.run(stop, "T#1s"_iec) == run_end::not_running);
  }

  TEST_CASE("event tasks are polled in real time") {
    bRealtimeEvent = FALSE;
    application plc{task<TICK_PRG>{"Tick", cyclic{"T#50ms"_iec}, 1},
                    task<EVENT_PRG>{"Event", event{bRealtimeEvent}, 0}};
    plc.start();
    std::atomic<bool> stop{false};
    realtime_runner runner{plc};
    CHECK(runner.run(stop, "T#20ms"_iec) == run_end::time_elapsed);
    CHECK(EVENT_PRG::instance().nRuns == 0U);
    bRealtimeEvent = TRUE;
    CHECK(runner.run(stop, "T#20ms"_iec) == run_end::time_elapsed);
    CHECK(EVENT_PRG::instance().nRuns == 1U);
    bRealtimeEvent = FALSE;
  }

  TEST_CASE("a run that asks for SCHED_FIFO runs whether it is granted or not") {
    application plc{task<TICK_PRG>{"Tick", cyclic{"T#5ms"_iec}, 0}};
    plc.start();
    std::atomic<bool> stop{false};
    realtime_runner runner{plc, realtime_options{.fifo = true, .fifo_priority = 10}};
    CHECK(runner.run(stop, "T#20ms"_iec) == run_end::time_elapsed);
    CHECK(TICK_PRG::instance().nCalls >= 1U);  // fifo_active() depends on the machine's rights
  }
}

TEST_CASE("the runner ends a cycle a simulation left under way, without running it again") {
  application plc{task<TICK_PRG>{"Tick", cyclic{"T#10ms"_iec}, 0}};
  plc.task(0).model_execution_time(LTIME("T#4ms"_iec));
  plc.start();
  plc.run_for("T#2ms"_iec);  // the cycle at 0 ms is under way, 2 ms left
  CHECK(TICK_PRG::instance().nCalls == 1U);
  std::atomic<bool> stop{false};
  realtime_runner runner{plc};
  CHECK(runner.run(stop, "T#5ms"_iec) == run_end::time_elapsed);
  CHECK(TICK_PRG::instance().nCalls == 1U);  // the next release is at 10 ms
  CHECK(plc.task(0).statistics().cycles == 1);
  plc.run_for("T#10ms"_iec);
  CHECK(TICK_PRG::instance().nCalls == 2U);
  CHECK(plc.task(0).statistics().cycles == 2);
}

TEST_CASE("run in slices, the application's clock keeps up with the wall clock") {
  application plc{task<TICK_PRG>{"Tick", cyclic{"T#5ms"_iec}, 0}};
  plc.start();
  std::atomic<bool> stop{false};
  realtime_runner runner{plc};
  const auto wall_start = std::chrono::steady_clock::now();
  CHECK(runner.run(stop, "T#20ms"_iec) == run_end::time_elapsed);
  std::this_thread::sleep_for(std::chrono::milliseconds(30));  // the caller's work between slices
  CHECK(runner.run(stop, "T#20ms"_iec) == run_end::time_elapsed);
  const auto wall = std::chrono::steady_clock::now() - wall_start;
  // The application's clock counts the 30 ms between the slices: about 70 ms in all.
  CHECK(plc.now() >= LTIME("T#70ms"_iec));
  CHECK(plc.now() <= LTIME(std::chrono::duration_cast<std::chrono::nanoseconds>(wall)));
  const task_statistics& s = plc.task(0).statistics();
  CHECK(s.overruns >= 5);  // the releases at 20, 25, ... 45 ms fell between the slices: one late, the others omitted
  CHECK(s.cycles + s.overruns <= static_cast<std::uint64_t>(plc.now().count() / 5000000 + 1));
}

namespace {
struct SLOW_PRG : program<SLOW_PRG> {
  var<UDINT> nCalls;
  void body() {
    nCalls = nCalls + 1U;
    const auto until = std::chrono::steady_clock::now() + std::chrono::milliseconds(3);
    while (std::chrono::steady_clock::now() < until) {
    }
  }
};
}  // namespace

TEST_CASE("overloaded (cycles longer than the interval), the runner still returns at its deadline") {
  application plc{task<SLOW_PRG>{"Slow", cyclic{"T#1ms"_iec}, 0}};
  plc.start();
  std::atomic<bool> stop{false};
  realtime_runner runner{plc};
  const auto wall_start = std::chrono::steady_clock::now();
  CHECK(runner.run(stop, "T#20ms"_iec) == run_end::time_elapsed);
  CHECK(std::chrono::steady_clock::now() - wall_start < std::chrono::milliseconds(500));
  CHECK(plc.task(0).statistics().overruns > 0);
}

TEST_CASE("huge max_sleep and event_poll settings still sleep") {
  application plc{task<TICK_PRG>{"Tick", cyclic{"T#50ms"_iec}, 0}};
  plc.start();
  std::atomic<bool> stop{false};
  realtime_options options;
  options.max_sleep = LTIME::max();
  options.event_poll = LTIME::max();
  realtime_runner runner{plc, options};
  const std::clock_t cpu_start = std::clock();
  CHECK(runner.run(stop, "T#200ms"_iec) == run_end::time_elapsed);
  const double cpu_ms = 1000.0 * static_cast<double>(std::clock() - cpu_start) / CLOCKS_PER_SEC;
  CHECK(cpu_ms < 100.0);  // busy-waiting would burn the whole 200 ms
}

TEST_CASE("a watchdog fault in real time stops the application and the run") {
  application plc{task<SLOW_PRG>{"Slow", cyclic{"T#10ms"_iec}, 0, watchdog{"T#1ms"_iec, 1}}};
  iecoop_test::fault_recorder faults;
  plc.start();
  std::atomic<bool> stop{false};
  realtime_runner runner{plc};
  CHECK(runner.run(stop, "T#1s"_iec) == run_end::not_running);  // the first 3 ms cycle overruns 1 ms
  CHECK(faults.count == 1);
  CHECK(faults.last_kind == fault_kind::watchdog);
  CHECK(plc.state() == application_state::exception);
  CHECK(SLOW_PRG::instance().nCalls == 1U);
}

#if defined(__linux__)
TEST_CASE("SCHED_FIFO is kept between runs in slices and given back when the runner ends") {
  const int before = sched_getscheduler(0);
  application plc{task<TICK_PRG>{"Tick", cyclic{"T#5ms"_iec}, 0}};
  plc.start();
  std::atomic<bool> stop{false};
  {
    realtime_runner runner{plc, realtime_options{.fifo = true, .fifo_priority = 10}};
    CHECK(runner.run(stop, "T#10ms"_iec) == run_end::time_elapsed);
    // Between two slices (printing, say) the thread keeps the policy it ran under: SCHED_FIFO
    // where it was granted (as root), the old one otherwise.
    CHECK(sched_getscheduler(0) == (runner.fifo_active() ? SCHED_FIFO : before));
    CHECK(runner.run(stop, "T#10ms"_iec) == run_end::time_elapsed);
    CHECK(sched_getscheduler(0) == (runner.fifo_active() ? SCHED_FIFO : before));
    runner.release_scheduling();
    CHECK_FALSE(runner.fifo_active());
    CHECK(sched_getscheduler(0) == before);
    CHECK(runner.run(stop, "T#10ms"_iec) == run_end::time_elapsed);  // asks again
  }
  CHECK(sched_getscheduler(0) == before);  // the runner's end gives the old policy back
}
#endif
