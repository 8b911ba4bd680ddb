// The scheduler (<iecoop/runtime/scheduler.hpp>) against a reference model, on 20,000 random
// task configurations.
//
// The scheduler jumps from one instant where something happens to the next. The model below
// is written separately, as plainly as possible: it steps time in ticks of 50 us (every
// interval, execution time, watchdog time and freewheeling pause of the configurations is a
// multiple of that) and at each tick applies the rules of docs/scheduler.md one by one —
// the cycle that used up its time ends; due tasks are released (a release that finds the
// previous cycle unfinished is an overrun); the processor goes to the highest priority, among equals to the
// cycle under way, then the earlier release, then the first task; a cycle's time is the
// model's cost; the freewheeling pause and the watchdog follow CODESYS's rules. Each
// configuration runs 40 ms; the two must agree on every cycle's start and end, on every
// task's statistics and on the watchdog fault. Event tasks are left out (their conditions
// are plain functions, tested in application_test.cpp), and so are releases missed while
// late: in simulation every release is an instant of its own, so none is ever late; against
// the steady clock they are (realtime_test.cpp).
#include <doctest/doctest.h>

#include <iecoop/runtime/scheduler.hpp>

#include <algorithm>
#include <array>
#include <cstddef>
#include <cstdint>
#include <random>
#include <string>
#include <vector>

#include "iecoop_test.hpp"

namespace {

using namespace iecoop;

// A program for task<...>{...}, whose settings the test compares with hand-written ones.
struct HOOKS_PRG : program<HOOKS_PRG> {
  void body() {}
};

constexpr std::uint64_t tick_ns = 50'000;  // 50 us
constexpr std::uint64_t run_ns = 40'000'000;
constexpr std::size_t max_tasks = 4;

struct event_record {
  bool begin;
  std::size_t task;
  std::uint64_t at;
  friend bool operator==(const event_record&, const event_record&) = default;
};

std::string describe(const std::vector<event_record>& trace, std::size_t from) {
  std::string text;
  for (std::size_t i = from; i < trace.size() && i < from + 6; ++i) {
    text += (trace[i].begin ? " begin " : " end ") + std::to_string(trace[i].task) + "@" +
            std::to_string(trace[i].at / 1000) + "us";
  }
  return text;
}

struct task_config {
  task_kind kind = task_kind::cyclic;
  std::uint8_t priority = 0;
  std::uint64_t interval = 0;            // ns, cyclic
  std::array<std::uint64_t, 8> costs{};  // ns; cycle n takes costs[n % 8]
  bool has_watchdog = false;
  std::uint64_t watchdog = 0;  // ns
  unsigned sensitivity = 1;
};

struct configuration {
  std::size_t tasks = 1;
  std::array<task_config, max_tasks> task{};
};

configuration random_configuration(std::mt19937_64& rng) {
  const auto pick = [&rng](std::uint64_t lo, std::uint64_t hi) {
    return std::uniform_int_distribution<std::uint64_t>(lo, hi)(rng);
  };
  configuration c;
  c.tasks = static_cast<std::size_t>(pick(1, max_tasks));
  for (std::size_t i = 0; i < c.tasks; ++i) {
    task_config& t = c.task[i];
    t.kind = pick(0, 3) == 0 ? task_kind::freewheeling : task_kind::cyclic;
    t.priority = static_cast<std::uint8_t>(pick(0, 3));  // ties are frequent
    t.interval = pick(1, 40) * 100'000;                  // 0.1 .. 4 ms
    const std::uint64_t heaviest = pick(0, 30);          // some configurations overload
    for (std::uint64_t& cost : t.costs) cost = pick(0, heaviest) * 100'000;
    t.has_watchdog = pick(0, 3) == 0;
    t.watchdog = pick(1, 40) * 100'000;
    t.sensitivity = static_cast<unsigned>(pick(1, 3));
  }
  return c;
}

// --- The model ------------------------------------------------------------------------

struct model_result {
  std::vector<event_record> trace;
  std::array<task_statistics, max_tasks> statistics{};
  int faulted_task = -1;
};

model_result run_model(const configuration& c) {
  struct state {
    bool released = false, active = false;
    std::uint64_t release_time = 0, start_time = 0, remaining = 0, next_release = 0, cycle = 0;
    std::uint32_t streak = 0;
  };
  model_result out;
  std::array<state, max_tasks> s{};
  std::uint64_t freewheeling = 0;
  for (std::size_t i = 0; i < c.tasks; ++i) freewheeling += c.task[i].kind == task_kind::freewheeling ? 1U : 0U;

  bool exception = false;
  const auto end = [&](std::size_t i, std::uint64_t now) {
    const task_config& t = c.task[i];
    s[i].active = false;
    out.trace.push_back({false, i, now});
    const std::uint64_t cycle_time = now - s[i].start_time;
    out.statistics[i].record(LTIME::from_ticks(s[i].start_time - s[i].release_time), LTIME::from_ticks(cycle_time));
    if (t.kind == task_kind::freewheeling) {
      // CODESYS: pause = cycle x (100 - L) / L with L = 80 % / 2 / (freewheeling tasks), at least 1 ms.
      const std::uint64_t pause = cycle_time * (200 * freewheeling - 80) / 80;
      s[i].next_release = now + std::max<std::uint64_t>(pause, 1'000'000);
    }
    if (t.has_watchdog) {
      if (cycle_time <= t.watchdog) {
        s[i].streak = 0;
        out.statistics[i].consecutive_watchdog_overruns = 0;
      } else {
        ++out.statistics[i].watchdog_overruns;
        out.statistics[i].consecutive_watchdog_overruns = ++s[i].streak;
        if (s[i].streak >= t.sensitivity || cycle_time > t.watchdog * t.sensitivity) {
          exception = true;
          out.faulted_task = static_cast<int>(i);
        }
      }
    }
  };
  const auto release = [&](std::size_t i, std::uint64_t at) {
    if (s[i].released || s[i].active) {
      ++out.statistics[i].overruns;
      ++out.statistics[i].consecutive_overruns;
      return;
    }
    s[i].released = true;
    s[i].release_time = at;
    out.statistics[i].consecutive_overruns = 0;
  };
  // The task that gets the processor, or -1.
  const auto choose = [&]() {
    int best = -1;
    for (std::size_t i = 0; i < c.tasks; ++i) {
      if (!s[i].released && !s[i].active) continue;
      if (best < 0) {
        best = static_cast<int>(i);
        continue;
      }
      const std::size_t b = static_cast<std::size_t>(best);
      const auto key = [&](std::size_t k) {
        return std::array<std::uint64_t, 4>{c.task[k].priority, s[k].active ? 0U : 1U,
                                            s[k].active ? 0 : s[k].release_time, k};
      };
      if (key(i) < key(b)) best = static_cast<int>(i);
    }
    return best;
  };

  for (std::uint64_t now = 0; now < run_ns && !exception; now += tick_ns) {
    // The cycle that used up its time ends.
    for (std::size_t i = 0; i < c.tasks && !exception; ++i) {
      if (s[i].active && s[i].remaining == 0) end(i, now);
    }
    if (exception) break;
    // Releases.
    for (std::size_t i = 0; i < c.tasks; ++i) {
      const task_config& t = c.task[i];
      if (s[i].next_release > now) continue;
      release(i, s[i].next_release);
      if (t.kind == task_kind::cyclic) {
        s[i].next_release += t.interval;
        while (s[i].next_release <= now) {  // missed while late: omitted
          ++out.statistics[i].overruns;
          ++out.statistics[i].consecutive_overruns;
          s[i].next_release += t.interval;
        }
      } else {
        s[i].next_release = UINT64_MAX;
      }
    }
    // Dispatch: start cycles, end those that take no time, until one needs the processor.
    int running = -1;
    for (int next = choose(); next >= 0 && !exception; next = choose()) {
      const auto i = static_cast<std::size_t>(next);
      if (!s[i].active) {
        s[i].released = false;
        s[i].active = true;
        s[i].start_time = now;
        s[i].remaining = c.task[i].costs[s[i].cycle % 8];
        ++s[i].cycle;
        out.trace.push_back({true, i, now});
        continue;
      }
      if (s[i].remaining > 0) {
        running = next;
        break;
      }
      end(i, now);
    }
    if (running >= 0) s[static_cast<std::size_t>(running)].remaining -= tick_ns;
  }
  return out;
}

// --- The scheduler ----------------------------------------------------------------------

// Queued: the scheduler keeps its ready queues even with so few tasks (detail::pick_by_scan,
// specialised below), so that both ways of picking the next task meet the model.
template <bool Queued>
struct recording_cycles_of {
  std::vector<event_record>* trace;
  void begin_cycle(std::size_t task, LTIME now) { trace->push_back({true, task, now.count()}); }
  void end_cycle(std::size_t task, LTIME now) { trace->push_back({false, task, now.count()}); }
};
using recording_cycles = recording_cycles_of<false>;

}  // namespace

template <std::size_t N>
inline constexpr bool iecoop::detail::pick_by_scan<N, recording_cycles_of<true>> = false;

namespace {

static_assert(sizeof(scheduler<4, recording_cycles>) < sizeof(scheduler<4, recording_cycles_of<true>>),
              "with four tasks the scheduler picks by looking at them, and keeps no ready queues");

LTIME cost_of(std::uint64_t cycle, void* context) {
  return LTIME::from_ticks(static_cast<const task_config*>(context)->costs[cycle % 8]);
}

template <std::size_t N, bool Queued>
model_result run_scheduler(const configuration& c) {
  model_result out;
  std::array<task_settings, N> settings{};
  for (std::size_t i = 0; i < N; ++i) {
    settings[i].kind = c.task[i].kind;
    settings[i].priority = c.task[i].priority;
    settings[i].interval = LTIME::from_ticks(c.task[i].interval);
    settings[i].has_watchdog = c.task[i].has_watchdog;
    settings[i].watchdog_time = LTIME::from_ticks(c.task[i].watchdog);
    settings[i].watchdog_sensitivity = c.task[i].sensitivity;
  }
  scheduler<N, recording_cycles_of<Queued>> s{settings, &out.trace};  // recording_cycles_of{&out.trace}
  for (std::size_t i = 0; i < N; ++i) s.task(i).model_execution_time(&cost_of, const_cast<task_config*>(&c.task[i]));
  s.start();
  s.run_until(LTIME::from_ticks(run_ns));
  for (std::size_t i = 0; i < N; ++i) out.statistics[i] = s.task(i).statistics();
  if (s.faulted_task() != nullptr) out.faulted_task = static_cast<int>(s.faulted_task() - &s.task(0));
  CHECK((s.state() == scheduler_state::exception) == (out.faulted_task >= 0));
  return out;
}

template <bool Queued>
model_result run_scheduler(const configuration& c) {
  switch (c.tasks) {
    case 1: return run_scheduler<1, Queued>(c);
    case 2: return run_scheduler<2, Queued>(c);
    case 3: return run_scheduler<3, Queued>(c);
    default: return run_scheduler<4, Queued>(c);
  }
}

bool same_statistics(const task_statistics& a, const task_statistics& b) {
  return a.cycles == b.cycles && a.last_cycle_time == b.last_cycle_time && a.min_cycle_time == b.min_cycle_time &&
         a.max_cycle_time == b.max_cycle_time && a.total_cycle_time == b.total_cycle_time &&
         a.last_jitter == b.last_jitter && a.min_jitter == b.min_jitter && a.max_jitter == b.max_jitter &&
         a.overruns == b.overruns && a.consecutive_overruns == b.consecutive_overruns &&
         a.watchdog_overruns == b.watchdog_overruns &&
         a.consecutive_watchdog_overruns == b.consecutive_watchdog_overruns;
}

TEST_SUITE("scheduler") {
  TEST_CASE("settings made at run time are checked at run time") {
    iecoop_test::fault_recorder faults;
    std::vector<event_record> trace;
    std::array<task_settings, 2> settings{};
    settings[0].priority = 40;  // above 31
    settings[0].interval = LTIME(TIME(1));
    settings[1].interval = LTIME{};  // cyclic without interval
    scheduler<2, recording_cycles> s{settings, &trace};
    CHECK(faults.count == 2);
    CHECK(faults.last_kind == fault_kind::invalid_value);
    CHECK(s.task(0).priority() == 31);
    s.start();
    s.run_until(LTIME(TIME(3)));
    CHECK(s.task(0).statistics().cycles == 3);  // 0, 1 and 2 ms
    CHECK(s.task(1).statistics().cycles == 0);  // never released
    CHECK(s.base_cycle() == LTIME(TIME(1)));
  }

  TEST_CASE("settings written by hand get the hooks of their kind and watchdog") {
    std::vector<event_record> trace;
    std::array<task_settings, 4> settings{};
    settings[0].interval = LTIME(TIME(1));
    settings[1].interval = LTIME(TIME(1));
    settings[1].has_watchdog = true;
    settings[1].watchdog_time = LTIME(TIME(2));
    settings[2].kind = task_kind::freewheeling;
    settings[3].kind = task_kind::freewheeling;
    settings[3].has_watchdog = true;
    settings[3].watchdog_time = LTIME(TIME(2));
    scheduler<4, recording_cycles> s{settings, &trace};
    CHECK(s.task(0).settings().hooks == nullptr);
    CHECK(s.task(1).settings().hooks == task<HOOKS_PRG>{"W", cyclic{TIME(1)}, 0, watchdog{TIME(2)}}.settings().hooks);
    CHECK(s.task(2).settings().hooks == task<HOOKS_PRG>{"F", freewheeling{}, 0}.settings().hooks);
    CHECK(s.task(3).settings().hooks == task<HOOKS_PRG>{"FW", freewheeling{}, 0, watchdog{TIME(2)}}.settings().hooks);
    // and the freewheeling task pauses: cycles of no time, so 1 ms apart.
    s.start();
    s.run_until(LTIME(TIME(5)));
    CHECK(s.task(2).statistics().cycles == 5);
  }

  TEST_CASE("stepped by hand, as a runner on another clock does") {
    std::vector<event_record> trace;
    std::array<task_settings, 2> settings{};
    settings[0].interval = LTIME(TIME(2));
    settings[0].priority = 1;
    settings[1].kind = task_kind::freewheeling;
    settings[1].priority = 9;
    scheduler<2, recording_cycles> s{settings, &trace};
    using S = decltype(s);
    CHECK(s.pick() == S::no_task);  // halted
    s.start();
    s.release_due();
    REQUIRE(s.pick() == 0);  // the higher priority first
    s.begin_cycle(0);
    s.advance_to(LTIME::from_ticks(300'000));
    s.end_cycle(0);
    REQUIRE(s.pick() == 1);
    s.begin_cycle(1);
    s.advance_to(LTIME::from_ticks(100'000));  // never back
    CHECK(s.now() == LTIME::from_ticks(300'000));
    s.advance_to(LTIME::from_ticks(500'000));
    s.end_cycle(1);
    CHECK(s.pick() == S::no_task);
    CHECK(s.next_release() == LTIME(TIME(1)) + LTIME::from_ticks(500'000));  // freewheeling: 1 ms pause at least
    CHECK(trace ==
          std::vector<event_record>{{true, 0, 0}, {false, 0, 300'000}, {true, 1, 300'000}, {false, 1, 500'000}});
    CHECK(s.task(0).statistics().last_cycle_time == LTIME::from_ticks(300'000));
    CHECK(s.task(1).statistics().last_jitter == LTIME::from_ticks(300'000));
  }
}

TEST_SUITE("scheduler against a reference model") {
  TEST_CASE("20000 random configurations of 1 to 4 cyclic and freewheeling tasks") {
    iecoop_test::fault_recorder faults;  // the watchdog faults some configurations provoke
    std::mt19937_64 rng(20261125);
    std::size_t cycles = 0, preempted = 0, overrun = 0, faulted = 0;
    for (int n = 0; n < 20000; ++n) {
      const configuration c = random_configuration(rng);
      const model_result expected = run_model(c);
      // Every configuration on both ways of picking the next task: looking at each task, and
      // the ready queues (a scheduler with more than four tasks).
      for (const bool queued : {false, true}) {
        const model_result actual = queued ? run_scheduler<true>(c) : run_scheduler<false>(c);
        const auto mismatch =
            std::mismatch(expected.trace.begin(), expected.trace.end(), actual.trace.begin(), actual.trace.end());
        const auto at = static_cast<std::size_t>(mismatch.first - expected.trace.begin());
        INFO("configuration ", n, " (", c.tasks, " tasks, ", queued ? "ready queues" : "picked by looking",
             "), first difference at event ", at, ": model", describe(expected.trace, at), " | scheduler",
             describe(actual.trace, at));
        REQUIRE(expected.trace == actual.trace);
        REQUIRE(expected.faulted_task == actual.faulted_task);
        for (std::size_t i = 0; i < c.tasks; ++i) {
          INFO("task ", i);
          REQUIRE(same_statistics(expected.statistics[i], actual.statistics[i]));
        }
      }
      for (std::size_t i = 0; i < c.tasks; ++i) {
        cycles += expected.statistics[i].cycles;
        overrun += expected.statistics[i].overruns > 0 ? 1U : 0U;
      }
      faulted += expected.faulted_task >= 0 ? 1U : 0U;
      // A begin while another cycle is under way is a preemption (or a zero-time cycle).
      std::size_t open = 0;
      for (const event_record& e : expected.trace) {
        if (e.begin && open > 0) ++preempted;
        open = e.begin ? open + 1 : open - 1;
      }
    }
    // The random configurations do exercise what they are meant to.
    CHECK(cycles > 500'000);
    CHECK(preempted > 10'000);
    CHECK(overrun > 1'000);
    CHECK(faulted > 1'000);
    MESSAGE(cycles, " cycles, ", preempted, " cycles begun over another, ", overrun, " tasks with overruns, ", faulted,
            " watchdog faults");
  }
}

}  // namespace
