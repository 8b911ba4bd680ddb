// SPDX-License-Identifier: MIT
// iecoop/runtime/task_settings.hpp — what a task is, apart from the programs it calls: its
// kind (cyclic, freewheeling, event), interval or trigger, priority and watchdog
// (task_settings), its statistics (task_statistics), and the hooks through which the scheduler
// reaches what only some tasks need at the end of a cycle (the freewheeling pause, the watchdog
// check). task<...>{...} (<iecoop/runtime/task.hpp>) makes the settings; the scheduler
// (<iecoop/runtime/scheduler.hpp>) runs them.
#pragma once

#include <cstddef>
#include <cstdint>

#include <iecoop/config.hpp>
#include <iecoop/detail/constant_division.hpp>
#include <iecoop/fault.hpp>
#include <iecoop/types/elementary.hpp>
#include <iecoop/types/time.hpp>

#include <iecoop/detail/push_macros.hpp>

namespace iecoop {

/// The three task types of CODESYS's task configuration that iecoop runs.
enum class task_kind : std::uint8_t {
  cyclic,        ///< released every interval
  freewheeling,  ///< released again as soon as its cycle ended and a pause has passed
  event,         ///< released on the rising edge of a BOOL
};

/// The short name of a task type: "cyclic", "freewheeling" or "event".
[[nodiscard]] constexpr const char* to_string(task_kind kind) noexcept {
  switch (kind) {
    case task_kind::cyclic: return "cyclic";
    case task_kind::freewheeling: return "freewheeling";
    case task_kind::event: return "event";
  }
  return "unknown";
}

// The task's settings are checked by the task's constructor, which is consteval: one immediate
// call per task, because Clang 14 crashes on a call whose arguments are several immediate
// invocations (a consteval `cyclic{...}` beside a consteval priority, say).

/// Type "Cyclic" with its interval (ST: INTERVAL := T#10ms), a TIME or LTIME greater than zero.
struct cyclic {
  constexpr cyclic(TIME every) noexcept : interval(every) {}   // implicit: reads as the configuration
  constexpr cyclic(LTIME every) noexcept : interval(every) {}  // implicit on purpose
  LTIME interval;
};

/// Type "Freewheeling": runs again and again, pausing after each cycle so that it leaves the
/// processor to others (see application::set_freewheeling_load).
struct freewheeling {};

/// Type "Event": the task runs once on each rising edge of a BOOL (ST: SINGLE := bTrigger),
/// given as a global variable (as CODESYS requires: the task is configured while compiling,
/// so the variable's address must be a constant) or as a function that reads the condition.
/// The application samples it whenever something happens (a task cycle starts or ends, a
/// cyclic task is released) and when a run starts.
struct event {
  /// The rising edge of this global variable releases the task.
  explicit constexpr event(const BOOL& variable) noexcept : variable_(&variable) {}
  /// The rising edge of what this function returns releases the task.
  explicit constexpr event(BOOL (*condition)()) noexcept : condition_(condition) {}

  /// The condition's value now.
  [[nodiscard]] BOOL read() const {
    if (variable_ != nullptr) return *variable_;
    return condition_ != nullptr ? condition_() : BOOL(false);
  }

 private:
  friend struct task_settings;
  template <class...>
  friend class task;
  constexpr event() noexcept = default;  // never fires: the trigger of a task that is no event task

  const BOOL* variable_ = nullptr;
  BOOL (*condition_)() = nullptr;
};

/// A task's watchdog (CODESYS: Watchdog, Time, Sensitivity): a cycle longer than `time` is an
/// overrun of the watchdog; the `sensitivity`-th overrun in a row (0 counts as 1), or a single
/// cycle longer than sensitivity x time, is a fault (fault_kind::watchdog), after which the
/// application stops in an exception state until it is reset. The time must be greater than zero.
struct watchdog {
  constexpr watchdog(TIME after, unsigned times = 1) noexcept : time(after), sensitivity(times == 0 ? 1U : times) {}
  constexpr watchdog(LTIME after, unsigned times = 1) noexcept : time(after), sensitivity(times == 0 ? 1U : times) {}
  LTIME time;
  unsigned sensitivity;
};

/**
 * A task's figures, as CODESYS's task monitor shows them (Task_Info2): cycles run, the cycle
 * time (from the cycle's start to its end, including the time higher-priority tasks took
 * from it) last/min/max/average, the jitter (how late the cycle started after its release)
 * last/min/max, overruns (releases skipped because the previous cycle had not ended:
 * CODESYS's omitted cycles) and watchdog overruns. All times in LTIME.
 */
struct task_statistics {
  std::uint64_t cycles = 0;
  LTIME last_cycle_time{};
  LTIME min_cycle_time{};
  LTIME max_cycle_time{};
  LTIME total_cycle_time{};
  LTIME last_jitter{};
  LTIME min_jitter{};
  LTIME max_jitter{};
  std::uint64_t overruns = 0;                       ///< releases skipped (omitted cycles)
  std::uint64_t watchdog_overruns = 0;              ///< cycles longer than the watchdog time
  std::uint32_t consecutive_overruns = 0;           ///< releases skipped in a row up to now
  std::uint32_t consecutive_watchdog_overruns = 0;  ///< watchdog overruns in a row up to now

  /// Average cycle time over all cycles (0 before the first).
  [[nodiscard]] constexpr LTIME average_cycle_time() const noexcept {
    return cycles == 0 ? LTIME{} : LTIME::from_ticks(total_cycle_time.count() / cycles);
  }
  /// Peak-to-peak jitter: max - min.
  [[nodiscard]] constexpr LTIME jitter_span() const noexcept { return max_jitter - min_jitter; }

  /// Records a finished cycle that started `jitter` after its release and took `cycle_time`.
  constexpr void record(LTIME jitter, LTIME cycle_time) noexcept {
    if (cycles == 0) {
      min_cycle_time = max_cycle_time = cycle_time;
      min_jitter = max_jitter = jitter;
    } else {
      if (cycle_time < min_cycle_time) min_cycle_time = cycle_time;
      if (cycle_time > max_cycle_time) max_cycle_time = cycle_time;
      if (jitter < min_jitter) min_jitter = jitter;
      if (jitter > max_jitter) max_jitter = jitter;
    }
    ++cycles;
    last_cycle_time = cycle_time;
    total_cycle_time += cycle_time;
    last_jitter = jitter;
  }
};

class task_state;  // <iecoop/runtime/scheduler.hpp>: the hooks below name it
namespace detail {
struct task_hooks;
}  // namespace detail

/// What every task has, whatever programs it calls.
// The small members together, before the 8-byte ones: 40 bytes on a 32-bit core, not 48.
struct task_settings {
  const char* name = "";
  task_kind kind = task_kind::cyclic;
  std::uint8_t priority = 31;
  bool has_watchdog = false;
  LTIME interval{};  ///< cyclic tasks
  event trigger{};   ///< event tasks
  LTIME watchdog_time{};
  unsigned watchdog_sensitivity = 1;
  /// What the task's kind and watchdog add to the end of its cycles (the freewheeling pause,
  /// the watchdog check): set by task<...>{...}, which knows both while compiling, so that an
  /// image refers only to the code its tasks need. Leave it null in settings written by hand:
  /// the scheduler then takes it from `kind` and `has_watchdog`. (On a 32-bit core it fills
  /// the last four bytes, which were padding.)
  const detail::task_hooks* hooks = nullptr;
};

namespace detail {

/// a + b, or LTIME::max() (which the scheduler treats as "never") if that would wrap. By the
/// addition's carry: on a 32-bit core two instructions and a branch (-40 B of the scheduler
/// example's flash on the Cortex-M3 against comparing with max() - a).
constexpr LTIME add_saturated(LTIME a, LTIME b) noexcept {
  const std::uint64_t sum = a.count() + b.count();  // unsigned: wraps
  return sum < a.count() ? LTIME::max() : LTIME::from_ticks(sum);
}

/// The parts of a task cycle's end that only some tasks need, as functions that a task's
/// settings point to (task_settings::hooks): a firmware image whose tasks are all cyclic and
/// without a watchdog links neither (docs/embedded.md, "Sizes").
struct task_hooks {
  /// A freewheeling task's pause after a cycle that took `cycle_time`, with `load` percent
  /// (1..100) of the processor for the `freewheeling_tasks` of the application; nullptr for
  /// the tasks of the other kinds.
  LTIME (*pause)(LTIME cycle_time, unsigned load, unsigned freewheeling_tasks) noexcept;
  /// The watchdog check of a cycle that took `cycle_time`: counts an overrun in the
  /// statistics and the task's streak; TRUE if it is a fault. nullptr without a watchdog.
  bool (*watchdog_fault)(const task_settings& settings, task_statistics& statistics, std::uint32_t& streak,
                         LTIME cycle_time) noexcept;
  /// Reports the watchdog fault of the task `name` (after the scheduler stopped the tasks).
  void (*report_watchdog_fault)(const char* name);
  /// What the scheduler calls at the end of a cycle of task `t` (one of the `count` tasks at
  /// `tasks`) that took `cycle_time`, at `now`, freewheeling tasks having `load` percent of the
  /// processor: the two above (end_hooked_cycle). TRUE if the watchdog found a fault. Reached
  /// through this pointer alone, so that an image whose tasks have no hooks links none of it.
  bool (*end_cycle)(task_state& t, const task_state* tasks, std::size_t count, LTIME now, LTIME cycle_time,
                    unsigned load) noexcept;
};

/// L = load / 2 / n percent of the processor for each of n freewheeling tasks; the pause is
/// cycle x (100 - L) / L = cycle x (200 n - load) / load, at least 1 ms. Its divisions are
/// 64-bit, which a 32-bit core makes in software: only a freewheeling task links them.
inline LTIME freewheeling_pause(LTIME cycle_time, unsigned load, unsigned freewheeling_tasks) noexcept {
  const std::uint64_t max_load = load;  // 1..100
  const std::uint64_t numerator = 200 * std::uint64_t{freewheeling_tasks} - max_load;
  const std::uint64_t whole = divide_u64(cycle_time.count(), max_load);
  const std::uint64_t rest = cycle_time.count() - whole * max_load;
  const LTIME pause = LTIME::from_ticks(whole * numerator + divide_u64(rest * numerator, max_load));
  const LTIME minimum = LTIME(TIME(1));
  return pause < minimum ? minimum : pause;
}

/// A cycle longer than the watchdog time is an overrun; the sensitivity-th in a row, or one
/// cycle longer than sensitivity x time, a fault. The streak is the scheduler's, apart from
/// the statistics, which a user may reset at any time.
inline bool watchdog_fault(const task_settings& settings, task_statistics& statistics, std::uint32_t& streak,
                           LTIME cycle_time) noexcept {
  if (cycle_time <= settings.watchdog_time) {
    streak = 0;
    statistics.consecutive_watchdog_overruns = 0;
    return false;
  }
  ++statistics.watchdog_overruns;
  statistics.consecutive_watchdog_overruns = ++streak;
  const unsigned sensitivity = settings.watchdog_sensitivity;
  const LTIME watchdog_time = settings.watchdog_time;
  const bool single_timeout =
      watchdog_time.count() <= LTIME::max().count() / sensitivity && cycle_time > watchdog_time * sensitivity;
  return streak >= sensitivity || single_timeout;
}

inline void report_watchdog_fault(const char* name) {
  fault_context context{name, nullptr, nullptr};  // current_task(): none, as outside a cycle
  const fault_context_scope in_task(context);
  fault(fault_kind::watchdog,
        "a task cycle overran its watchdog (time x sensitivity); the application stopped in exception");
}

/// task_hooks::end_cycle: the freewheeling pause (the task's next release) and the watchdog
/// check, through the hooks of the task's settings. State is task_state (a template parameter:
/// this header only names it, <iecoop/runtime/scheduler.hpp> defines it).
template <class State>
bool end_hooked_cycle(State& t, const State* tasks, std::size_t count, LTIME now, LTIME cycle_time,
                      unsigned load) noexcept {
  const task_hooks& hooks = *t.settings_.hooks;
  if (hooks.pause != nullptr) {
    unsigned freewheeling_tasks = 0;
    for (std::size_t i = 0; i < count; ++i) {
      freewheeling_tasks += tasks[i].settings_.kind == task_kind::freewheeling ? 1U : 0U;
    }
    t.next_release_ = add_saturated(now, hooks.pause(cycle_time, load, freewheeling_tasks));
  }
  return hooks.watchdog_fault != nullptr &&
         hooks.watchdog_fault(t.settings_, t.statistics_, t.watchdog_streak_, cycle_time);
}

// The three sets of hooks (State: task_state).
template <class State>
inline constexpr task_hooks freewheeling_hooks{&freewheeling_pause, nullptr, nullptr, &end_hooked_cycle<State>};
template <class State>
inline constexpr task_hooks watchdog_hooks{nullptr, &watchdog_fault, &report_watchdog_fault, &end_hooked_cycle<State>};
template <class State>
inline constexpr task_hooks freewheeling_watchdog_hooks{&freewheeling_pause, &watchdog_fault, &report_watchdog_fault,
                                                        &end_hooked_cycle<State>};

/// The hooks of a task of `kind`, with a watchdog or without (nullptr: none needed); State is
/// task_state (task<...>{...} and the scheduler name it).
template <class State>
constexpr const task_hooks* hooks_for(task_kind kind, bool has_watchdog) noexcept {
  if (kind == task_kind::freewheeling) {
    return has_watchdog ? &freewheeling_watchdog_hooks<State> : &freewheeling_hooks<State>;
  }
  return has_watchdog ? &watchdog_hooks<State> : nullptr;
}

}  // namespace detail

}  // namespace iecoop

#include <iecoop/detail/pop_macros.hpp>
