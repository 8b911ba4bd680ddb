// SPDX-License-Identifier: MIT
// iecoop/runtime/scheduler.hpp — the scheduler: when each task's cycles start and end. It
// knows the tasks (their settings, states and statistics), the clock, the releases, the
// dispatch by priority, the watchdog and the simulated advance of time; it knows nothing of
// programs, the process image or RETAIN. What a cycle does is the `Cycles` object's part
// (concept TaskCycles): the scheduler calls its begin_cycle(task, now) when a cycle starts
// and end_cycle(task, now) when it ends.
//
//     scheduler<2, my_cycles> s{{fast_settings, slow_settings}};   // + my_cycles' arguments
//     s.start();                          // tasks released from now() on
//     s.run_until("LTIME#1s"_iec);        // simulated: jumps from event to event
//
// An application (<iecoop/runtime/application.hpp>) composes a scheduler with its programs,
// process image and retain memory; the real-time runner (<iecoop/runtime/realtime.hpp>)
// drives the same scheduler against the steady clock through the stepping API (advance_to,
// release_due, pick, begin_cycle, end_cycle), as does a test that wants to.
//
// The rules (CODESYS's, docs/scheduler.md): the processor goes to the highest priority (0
// highest) among the tasks released or under way; among equals, to the cycle under way, then
// the earlier release, then the task first in the configuration. A release that finds the
// task's previous cycle unfinished is skipped and counted as an overrun. A task's execution
// time is zero in simulation unless modelled (task_state::model_execution_time).
#pragma once

#include <array>
#include <concepts>
#include <cstddef>
#include <cstdint>
#include <span>
#include <string_view>
#include <type_traits>

#include <iecoop/config.hpp>
#include <iecoop/detail/constant_division.hpp>
#include <iecoop/detail/ready_queues.hpp>
#include <iecoop/fault.hpp>
#include <iecoop/runtime/cycle_observer.hpp>
#include <iecoop/runtime/task_info.hpp>
#include <iecoop/runtime/task_settings.hpp>
#include <iecoop/types/string.hpp>
#include <iecoop/types/time.hpp>

#include <iecoop/detail/push_macros.hpp>

namespace iecoop {

template <std::size_t N, class Cycles>
class scheduler;

/**
 * A task as the scheduler runs it: its settings, its statistics, its cycle (the task_info it
 * is, which code inside a block reads as current_task() during the task's cycles), and the
 * execution time a simulation gives its cycles.
 */
class task_state : public task_info {
 public:
  /// Starts the statistics afresh (CODESYS: IecTaskResetStatistics).
  void reset_statistics() noexcept { statistics_ = task_statistics{}; }

  /// TRUE while a cycle is released or under way.
  [[nodiscard]] bool busy() const noexcept { return released_ || active_; }
  /// TRUE while a cycle is under way (begun, not ended).
  [[nodiscard]] bool active() const noexcept { return active_; }

  /// Calls `observer` once per cycle of this task, after the cycle's programs ran (see
  /// cycle_observer): a trace recorder or a watch list samples the task's variables there.
  void attach(cycle_observer& observer) noexcept { observers_.attach(observer); }

  /// In simulation, each cycle of this task takes `each_cycle` of processor time.
  void model_execution_time(LTIME each_cycle) noexcept {
    cost_constant_ = each_cycle;
    cost_function_ = nullptr;
  }
  /// In simulation, cycle number n (0, 1, ... since start) takes cost(n, context).
  void model_execution_time(LTIME (*cost)(std::uint64_t cycle, void* context), void* context = nullptr) noexcept {
    cost_function_ = cost;
    cost_context_ = context;
  }

 private:
  // The scheduler is this class's other half: the state below is what it schedules with.
  template <std::size_t, class>
  friend class scheduler;
  template <class State>
  friend bool detail::end_hooked_cycle(State&, const State*, std::size_t, LTIME, LTIME, unsigned) noexcept;

  [[nodiscard]] LTIME cost_of(std::uint64_t cycle) const {
    return cost_function_ != nullptr ? cost_function_(cycle, cost_context_) : cost_constant_;
  }

  // The settings, statistics, cycle number, release and start times are task_info's. The
  // four bytes first: they fill task_info's last four (208 bytes in all on a 32-bit core).
  bool released_ = false;
  bool active_ = false;
  bool event_previous_ = false;
  std::uint8_t level_ = 0;             // its priority's level in the ready queues (detail::priority_level);
                                       // 0 where a scan picks the task (pick_by_scan: by priority)
  LTIME next_release_ = LTIME::max();  // cyclic and freewheeling tasks
  LTIME remaining_{};                  // simulated processor time the running cycle still needs
  LTIME cost_constant_{};
  LTIME (*cost_function_)(std::uint64_t, void*) = nullptr;
  void* cost_context_ = nullptr;
  detail::cycle_observer_list observers_;
  std::uint32_t watchdog_streak_ = 0;  // watchdog overruns in a row
#if UINTPTR_MAX > 0xFFFFFFFFU
  // 280 bytes on a 64-bit host, not the members' 248: the dispatch loop finds a task by its
  // index, and GCC 12 recomputes index x 240 (four instructions) or index x 256 (a shift) at
  // each use of the task, where it keeps index x 280 (one multiply): callgrind's task cycle
  // was 240, 225 and 218 instructions at 240, 256 and 280 bytes (docs/performance.md
  // "Scheduler"). A 32-bit core keeps its 208 bytes.
  std::byte pad_for_indexing_[32]{};
#endif
};
#if UINTPTR_MAX > 0xFFFFFFFFU
static_assert(sizeof(task_state) == 280,
              "iecoop: a task's state is 280 bytes on a 64-bit host; adjust pad_for_indexing_");
#endif

/// What a scheduler drives: the work of a task cycle, at its start and at its end. `task` is
/// the task's index in the configuration, `now` the scheduler's time.
/// begin_cycle may take the task's observers and the cycle's number too, and call the
/// observers itself (before and after the programs: the application's task cycles do).
template <class C>
concept TaskCycles = requires(C& cycles, std::size_t task, LTIME now) { cycles.end_cycle(task, now); } &&
                     (
                         requires(C& cycles, std::size_t task, LTIME now) { cycles.begin_cycle(task, now); } ||
                         requires(C& cycles, std::size_t task, LTIME now, const detail::cycle_observer_list& observers,
                                  std::uint64_t cycle) { cycles.begin_cycle(task, now, observers, cycle); });

/// Whether a scheduler's tasks run.
enum class scheduler_state : std::uint8_t {
  halted,     ///< no task runs (before start(), after halt() or restart())
  running,    ///< tasks are released and run
  exception,  ///< a watchdog fault stopped the tasks; restart() or halt() leaves this state
};

namespace detail {
/// The scheduler's constructor for settings made by task<...>{...}, whose hooks are set.
struct hooks_from_tasks_t {
  explicit hooks_from_tasks_t() = default;
};
inline constexpr hooks_from_tasks_t hooks_from_tasks{};
}  // namespace detail

/**
 * The scheduler of `N` tasks whose cycles a `Cycles` it holds carries out. Not copyable or
 * movable (a runner or an application keeps a reference to it); not thread-safe: drive it
 * from one thread.
 */
template <std::size_t N, class Cycles>
class scheduler {
  static_assert(N > 0, "iecoop: a scheduler needs at least one task; add task<PRG>{...}");
  static_assert(N <= 32767, "iecoop: a scheduler runs at most 32767 tasks; split the application");
  static_assert(
      TaskCycles<Cycles>,
      "iecoop: a scheduler's Cycles type does a task cycle's work; give it begin_cycle(std::size_t task, LTIME now) "
      "and end_cycle(std::size_t task, LTIME now)");

 public:
  /// The value of pick() when no task is ready.
  static constexpr std::size_t no_task = N;

  /// The tasks `settings`, in configuration order, whose cycles a Cycles made from
  /// `cycles_arguments` carries out. A priority above 31 reports fault_kind::invalid_value and
  /// is taken as 31; a cyclic task without an interval reports it too, and is never released.
  /// (task<...>{...} checks both while compiling.)
  template <class... Args>
  explicit scheduler(const std::array<task_settings, N>& settings, Args&&... cycles_arguments) noexcept
      : cycles_{static_cast<Args&&>(cycles_arguments)...} {
    configure<true>([&settings](std::size_t i) -> const task_settings& { return settings[i]; });
  }
  /// The same, for settings that task<...>{...} made (an application's): checked while
  /// compiling, and their hooks the ones the tasks need — the scheduler refers to no other
  /// (task_settings::hooks) and carries no run-time check of them.
  template <class... Args>
  scheduler(detail::hooks_from_tasks_t, const std::array<const task_settings*, N>& settings,
            Args&&... cycles_arguments) noexcept
      : cycles_{static_cast<Args&&>(cycles_arguments)...} {
    configure<false>([&settings](std::size_t i) -> const task_settings& { return *settings[i]; });
  }
  scheduler(const scheduler&) = delete;
  scheduler& operator=(const scheduler&) = delete;

  /// The object that carries out the cycles.
  [[nodiscard]] Cycles& cycles() noexcept { return cycles_; }
  [[nodiscard]] const Cycles& cycles() const noexcept { return cycles_; }

  // --- State ------------------------------------------------------------------------

  [[nodiscard]] scheduler_state state() const noexcept { return state_; }

  /// Runs the tasks: cyclic and freewheeling tasks are released from now() on. Does nothing
  /// when running; FALSE in the exception state (restart() first).
  bool start() noexcept {
    if (state_ == scheduler_state::exception) return false;
    if (state_ == scheduler_state::running) return true;
    state_ = scheduler_state::running;
    for (task_state& t : tasks_) {
      if (t.settings_.kind == task_kind::event) continue;
      const bool never = t.settings_.kind == task_kind::cyclic && t.settings_.interval == LTIME{};
      t.next_release_ = never ? LTIME::max() : now_;
    }
    return true;
  }

  /// Stops the tasks: releases and cycles under way are forgotten, an exception is cleared;
  /// the statistics stay. start() runs the tasks again.
  void halt() noexcept {
    clear_schedules();
    faulted_task_ = nullptr;
    state_ = scheduler_state::halted;
  }

  /// The tasks as after a download: halted, no cycle under way, statistics, cycle numbers,
  /// watchdog streaks and event memories cleared.
  void restart() noexcept {
    halt();
    for (task_state& t : tasks_) {
      t.reset_statistics();
      t.watchdog_streak_ = 0;
      t.cycle_number_ = 0;
      t.event_previous_ = false;
      t.last_exec_time_ = LTIME{};
      t.overran_ = false;
    }
  }

  // --- Simulated time ---------------------------------------------------------------

  /// The scheduler's time: simulated, or a real clock's as a runner advances it.
  [[nodiscard]] LTIME now() const noexcept { return now_; }

  /// Runs every task that is due before `until`, jumping from one instant where something
  /// happens (a release, the end of a cycle that has execution time) to the next, and leaves
  /// now() at `until`. Time passes also while the tasks do not run.
  void run_until(LTIME until) {
    if (until <= now_) return;
    while (state_ == scheduler_state::running) {
      process_instant();
      const LTIME next = next_instant();
      if (next >= until || state_ != scheduler_state::running) break;
      move_clock(next);  // next > now_: something happens at every instant
    }
    move_clock(until);
  }

  /// run_until(now() + duration).
  void run_for(LTIME duration) { run_until(detail::add_saturated(now_, duration)); }

  /// The shortest interval of a cyclic task, or 1 ms without one.
  [[nodiscard]] LTIME base_cycle() const noexcept {
    LTIME base = LTIME::max();
    for (const task_state& t : tasks_) {
      if (t.settings_.kind == task_kind::cyclic && t.settings_.interval != LTIME{} && t.settings_.interval < base) {
        base = t.settings_.interval;
      }
    }
    return base == LTIME::max() ? LTIME(TIME(1)) : base;
  }

  // --- Stepping: for a runner that follows another clock ------------------------------

  /// Moves the clock forward to `t` (never back); the cycle run_until() left running uses up
  /// the time passed.
  void advance_to(LTIME t) noexcept {
    if (t > now_) move_clock(t);
  }

  /// Releases, at now(), every cyclic or freewheeling task that is due and every event task
  /// whose condition rose. A release that finds the previous cycle unfinished is skipped (an
  /// overrun); the releases a cyclic task missed while late are omitted and counted.
  void release_due() {
    if (state_ == scheduler_state::running) release_due_now();
  }

  /// The task that gets the processor: the highest priority among those released or under
  /// way; among equals, the one under way before those released, then the earlier release,
  /// then the first in the configuration. no_task if none (or not running). O(1) with more than
  /// four tasks (ready queues), a look at each task with up to four (detail::pick_by_scan).
  [[nodiscard]] std::size_t pick() const noexcept {
    return state_ == scheduler_state::running ? pick_ready() : no_task;
  }

  /// Starts, at now(), a cycle of the released task `index` (as pick() chose it): the cycles'
  /// begin_cycle() does its work.
  void begin_cycle(std::size_t index) {
    task_state& t = task_at(index);
    ready_.begin(index, t.level_);
    start_cycle(t, index, t.cost_of(t.cycle_number_));
  }

  /// Ends, at now(), the cycle of task `index` under way: the cycles' end_cycle() does its
  /// work, then the statistics and the watchdog are updated. A watchdog fault (the
  /// sensitivity-th overrun in a row, or one cycle longer than sensitivity x time) puts the
  /// scheduler in the exception state and reports fault_kind::watchdog.
  // Not inlined: the dispatch loop then inlines finish_cycle() for the cycles that take no
  // time, the common case (GCC inlines one of the two, not both: 229 instructions against 233).
  [[gnu::noinline]] void end_cycle(std::size_t index) {
    task_state& t = task_at(index);
    ready_.end(t.level_);
    finish_cycle(t, index);
  }

  /// Ends, at now(), the cycles left under way (for a runner that takes over from run_until()).
  void finish_cycles() {
    running_ = no_task;
    for (std::size_t i = 0; i < N; ++i) {
      if (task_at(i).active_ && state_ == scheduler_state::running) end_cycle(i);
    }
  }

  /// The earliest release of a cyclic or freewheeling task (LTIME::max() if none is pending).
  [[nodiscard]] LTIME next_release() const noexcept {
    LTIME next = LTIME::max();
    for (const task_state& t : tasks_) {
      if (t.next_release_ < next) next = t.next_release_;
    }
    return next;
  }

  /// TRUE if some task is an event task (whose condition a runner must sample).
  [[nodiscard]] bool has_event_tasks() const noexcept { return has_event_tasks_; }

  // --- Tasks ------------------------------------------------------------------------

  [[nodiscard]] static constexpr std::size_t task_count() noexcept { return N; }
  /// The task at `index` in the configuration; an index out of range reports
  /// fault_kind::invalid_value and yields the first task.
  [[nodiscard]] task_state& task(std::size_t index) noexcept { return task_at(checked_index(index)); }
  [[nodiscard]] const task_state& task(std::size_t index) const noexcept { return task_at(checked_index(index)); }
  /// The task called `name`; an unknown name reports fault_kind::invalid_value and yields the first task.
  [[nodiscard]] task_state& task(std::string_view name) noexcept {
    for (task_state& t : tasks_) {
      if (detail::same_text(t.settings_.name, name)) return t;  // (no strlen, no memcmp)
    }
    fault(fault_kind::invalid_value, "no task of this name in the application; the first task stands in");
    return task_at(0);
  }
  [[nodiscard]] std::span<task_state, N> tasks() noexcept { return tasks_; }
  [[nodiscard]] std::span<const task_state, N> tasks() const noexcept { return tasks_; }

  /// The task whose watchdog put the scheduler in the exception state, or nullptr.
  [[nodiscard]] const task_state* faulted_task() const noexcept { return faulted_task_; }

  /// The processor load freewheeling tasks may use, in percent (CODESYS: 80 by default).
  /// A freewheeling task pauses after each cycle for cycle time x (100 - L) / L, at least
  /// 1 ms, where L = min(100, percent) / 2 / (number of freewheeling tasks).
  void set_freewheeling_load(unsigned percent) noexcept {
    freewheeling_load_ = static_cast<std::uint8_t>(percent == 0 ? 1 : percent < 100 ? percent : 100);
  }

 private:
  // The tasks' settings, settings_of(i) the i-th's.
  template <bool ByHand, class SettingsOf>
  void configure(SettingsOf settings_of) noexcept {
    std::uint32_t priorities = 0;  // the priorities the tasks have, as bits
    for (std::size_t i = 0; i < N; ++i) {
      task_settings& s = task_at(i).settings_;
      s = settings_of(i);
      if constexpr (ByHand) {
        if (s.priority > 31) {
          fault(fault_kind::invalid_value, "a task priority is 0 (highest) to 31 (lowest); 31 stands in");
          s.priority = 31;
        }
        if (s.kind == task_kind::cyclic && s.interval == LTIME{}) {
          fault(fault_kind::invalid_value,
                "a cyclic task needs an interval greater than zero; the task is never released");
        }
        // Settings written by hand: the hooks their kind and watchdog need.
        if (s.hooks == nullptr) s.hooks = detail::hooks_for<task_state>(s.kind, s.has_watchdog);
      } else if (s.priority > 31) {
        s.priority = 31;  // (only where Clang 14 ran task<...>{...} at run time, which reported it)
      }
      task_at(i).index_ = static_cast<std::int16_t>(i);
      has_event_tasks_ = has_event_tasks_ || s.kind == task_kind::event;
      if constexpr (!by_scan) priorities |= std::uint32_t{1} << s.priority;
    }
    if constexpr (!by_scan) {  // the ready queues' levels (a scan compares the priorities)
      for (task_state& t : tasks_)
        t.level_ = static_cast<std::uint8_t>(detail::priority_level(priorities, t.settings_.priority));
    }
  }

  // begin_cycle() after the ready queues: the cycle, which takes `cost` of processor time, starts.
  void start_cycle(task_state& t, std::size_t index, LTIME cost) {
    t.released_ = false;
    t.active_ = true;
    t.remaining_ = cost;
    t.record_begin(now_);
    // fault() and current_task() in the programs. A local: the programs run within this call.
    fault_context context{t.settings_.name, nullptr, &t};
    const detail::fault_context_scope in_task(context);
    if constexpr (requires { cycles_.begin_cycle(index, now_, t.observers_, t.cycle_number_); }) {
      cycles_.begin_cycle(index, now_, t.observers_, t.cycle_number_ - 1);  // calls the observers itself
    } else {
      cycles_.begin_cycle(index, now_);
      t.observers_.notify(now_, t.cycle_number_ - 1);
    }
  }

  // end_cycle() after the ready queues.
  void finish_cycle(task_state& t, std::size_t index) {
    t.active_ = false;
    t.remaining_ = LTIME{};
    cycles_.end_cycle(index, now_);
    const LTIME cycle_time = t.record_end(now_);
    // The freewheeling pause and the watchdog through the task's hooks (task_settings::hooks),
    // which only the tasks that need them have: an image without such a task links neither.
    const detail::task_hooks* const hooks = t.settings_.hooks;
    if (hooks != nullptr && hooks->end_cycle(t, tasks_.data(), N, now_, cycle_time, freewheeling_load_)) {
      watchdog_exception(t, *hooks);
    }
  }

  // A task's watchdog found a fault: the tasks stop, in the exception state.
  [[gnu::noinline, gnu::cold]] void watchdog_exception(task_state& t, const detail::task_hooks& hooks) {
    state_ = scheduler_state::exception;
    faulted_task_ = &t;
    clear_schedules();
    hooks.report_watchdog_fault(t.settings_.name);
  }

  // release_due() while running.
  void release_due_now() {
    for (task_state& t : tasks_) {
      if (t.settings_.kind == task_kind::event || t.next_release_ > now_) continue;
      release(index_of(t), t.next_release_);
      if (t.settings_.kind == task_kind::cyclic) {
        t.next_release_ = detail::add_saturated(t.next_release_, t.settings_.interval);
        if (t.next_release_ <= now_) skip_missed_releases(t);
      } else {
        t.next_release_ = LTIME::max();  // freewheeling: released again when the cycle ends
      }
    }
    sample_events();
  }

  // Releases missed while late are omitted (counted as overruns). Apart, and not inlined: the
  // only 64-bit division of a cyclic task's release, which a 32-bit core makes in software
  // (docs/embedded.md, "64-bit divisions").
  [[gnu::noinline, gnu::cold]] void skip_missed_releases(task_state& t) noexcept {
    const std::uint64_t missed = detail::divide_u64((now_ - t.next_release_).count(), t.settings_.interval.count()) + 1;
    t.record_overruns(missed);
    t.next_release_ = detail::add_saturated(t.next_release_, t.settings_.interval * missed);
  }

  // The clock moves forward to t > now_; the cycle left running uses up the time passed.
  void move_clock(LTIME t) noexcept {
    if (running_ != no_task) {
      task_state& r = task_at(running_);
      const LTIME spent = t - now_;
      r.remaining_ = spent < r.remaining_ ? r.remaining_ - spent : LTIME{};
    }
    now_ = t;
  }

  static std::size_t checked_index(std::size_t index) noexcept {
    if (index < N) return index;
    fault(fault_kind::invalid_value, "no task at this index in the application; the first task stands in");
    return 0;
  }
  // The task at `index` < N, through the array's pointer rather than its operator[]: GCC 12
  // merges the functions whose code is the same for two values of N (release() is, where up to
  // four tasks keep no ready queues) and, inlining the merged one into the other scheduler,
  // warns that the other N's array overruns the object (-Warray-bounds at -O2 and above).
  task_state& task_at(std::size_t index) noexcept { return tasks_.data()[index]; }
  const task_state& task_at(std::size_t index) const noexcept { return tasks_.data()[index]; }
  std::size_t index_of(const task_state& t) const noexcept { return static_cast<std::size_t>(&t - tasks_.data()); }

  void sample_events() {
    if (!has_event_tasks_) return;
    for (task_state& t : tasks_) {
      if (t.settings_.kind != task_kind::event) continue;
      const bool value = static_cast<bool>(t.settings_.trigger.read());
      if (value && !t.event_previous_) release(index_of(t), now_);
      t.event_previous_ = value;
    }
  }

  // The task to run: with few tasks, the first of the busy ones in dispatch order (pick()'s
  // rules, detail::pick_by_scan), else the ready queues' choice.
  [[nodiscard]] std::size_t pick_ready() const noexcept {
    if constexpr (by_scan) {
      std::size_t best = no_task;
      for (std::size_t i = 0; i < N; ++i) {
        if (task_at(i).busy() && (best == no_task || goes_before(task_at(i), task_at(best)))) best = i;
      }
      return best;
    } else {
      return ready_.pick();
    }
  }
  // Whether busy task a goes before busy task b, which comes earlier in the configuration:
  // the higher priority, then the cycle under way, then the earlier release.
  static bool goes_before(const task_state& a, const task_state& b) noexcept {
    if (a.settings_.priority != b.settings_.priority) return a.settings_.priority < b.settings_.priority;
    if (a.active_ != b.active_) return a.active_;
    return a.release_time_ < b.release_time_;
  }

  void release(std::size_t index, LTIME at) noexcept {
    task_state& t = task_at(index);
    if (t.busy()) {
      t.record_overruns(1);
      return;
    }
    t.released_ = true;
    t.release_time_ = at;
    t.statistics_.consecutive_overruns = 0;
    ready_.release(index, t.level_, [this](std::size_t a, std::size_t b) {
      return task_at(a).release_time_ < task_at(b).release_time_ ||
             (task_at(a).release_time_ == task_at(b).release_time_ && a < b);
    });
  }

  // Forget every release and cycle under way (a stop, a reset, an exception).
  void clear_schedules() noexcept {
    for (task_state& t : tasks_) {
      t.released_ = t.active_ = t.overrun_pending_ = false;
      t.remaining_ = LTIME{};
    }
    ready_.clear();
    running_ = no_task;
  }

  /// Everything that happens at now_: the running cycle ends if its time is used up, tasks
  /// are released, and the processor goes to the highest-priority task — whose cycle starts
  /// if it had not (and the choice is made again, as the cycle's code may have raised an
  /// event); cycles that take no time end at once.
  void process_instant() {
    if (running_ != no_task && task_at(running_).remaining_ == LTIME{}) {
      const std::size_t done = running_;
      running_ = no_task;
      end_cycle(done);
    }
    if (state_ != scheduler_state::running) return;
    release_due_now();
    while (state_ == scheduler_state::running) {
      const std::size_t next = pick_ready();
      if (next == no_task) break;
      task_state& t = task_at(next);
      if (!t.active_) {
        if (!has_event_tasks_) {
          // Nothing its code does can release a task: a cycle that takes no processor time
          // begins and ends at once, never queued as under way.
          const LTIME cost = t.cost_of(t.cycle_number_);
          if (cost == LTIME{}) {
            ready_.begin_and_end(next, t.level_);
            start_cycle(t, next, cost);
            if (state_ == scheduler_state::running) finish_cycle(t, next);
            continue;
          }
          ready_.begin(next, t.level_);
          start_cycle(t, next, cost);
          if (state_ != scheduler_state::running) break;
        } else {
          begin_cycle(next);
          sample_events();  // its code may have raised an event of a higher-priority task:
          continue;         // that one preempts the cycle right away
        }
      }
      if (t.remaining_ != LTIME{}) {
        running_ = static_cast<detail::task_index_t<N>>(next);
        return;
      }
      end_cycle(next);
      sample_events();  // a condition may read what the cycle's end wrote to the field
    }
    running_ = no_task;
  }

  /// The next instant where something happens: the running cycle ends or a task is released.
  [[nodiscard]] LTIME next_instant() const noexcept {
    const LTIME release = next_release();
    if (running_ == no_task) return release;
    const LTIME end = detail::add_saturated(now_, task_at(running_).remaining_);
    return end < release ? end : release;
  }

  Cycles cycles_;
  std::array<task_state, N> tasks_{};
  static constexpr bool by_scan = detail::pick_by_scan<N, Cycles>;
  [[no_unique_address]] std::conditional_t<by_scan, detail::no_ready_queues, detail::ready_queues<N>> ready_{};
  LTIME now_{};
  const task_state* faulted_task_ = nullptr;
  detail::task_index_t<N> running_ = no_task;
  std::uint8_t freewheeling_load_ = 80;  // percent, 1..100
  bool has_event_tasks_ = false;
  scheduler_state state_ = scheduler_state::halted;
};

}  // namespace iecoop

#include <iecoop/detail/pop_macros.hpp>
