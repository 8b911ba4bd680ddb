// SPDX-License-Identifier: MIT
// iecoop/runtime/task_info.hpp — what code inside a block knows of the task that runs it: its
// name and index, its interval, the cycle's number, start and first-cycle flag, the previous
// cycle's execution time and whether the task overran — TwinCAT's
// `_TaskInfo[GETCURTASKINDEXEX()]`, CODESYS's `__CURRENTTASK` and Task_Info2.
//
//     // tCycle := UDINT_TO_TIME(_TaskInfo[GETCURTASKINDEXEX()].CycleTime / 10000);   (TwinCAT)
//     tCycle = TIME(current_task().interval());
//     tCycle = UDINT_TO_TIME(F_GetTaskInfo().CycleTime / 10000U);   // the same, TwinCAT's way
//
// current_task() is the task whose cycle runs the calling code: the scheduler makes it current
// while the cycle's programs (and the task's cycle observers) run, whoever drives the
// scheduler — run_for() in simulated time, the real-time runner, a firmware's SysTick loop,
// the test kit's testing::plc; testing::cycles gives the block it drives a task of its own. A
// block called from two tasks sees each in its turn; a program called by another sees the
// caller's task. Outside a task cycle (FB_Init at start(), code between two run_for() calls)
// it is a "no task": index -1, name "", interval 0, no cycle counted — never a fault.
//
// Cost: the scheduler sets one pointer when a cycle starts and restores it when the programs
// have returned; reading is a load and a test. F_GetTaskInfo() converts to TwinCAT's units and
// copies the name when it is called, and only then. Nothing allocates.
#pragma once

#include <cstdint>

#include <iecoop/config.hpp>
#include <iecoop/detail/constant_division.hpp>
#include <iecoop/fault.hpp>
#include <iecoop/runtime/task_settings.hpp>
#include <iecoop/types/elementary.hpp>
#include <iecoop/types/string.hpp>
#include <iecoop/types/time.hpp>

#include <iecoop/detail/push_macros.hpp>

namespace iecoop {

namespace detail {
struct task_info_driver;
}  // namespace detail

/**
 * What a task knows of itself and of its cycle: its settings, its statistics, the cycle under
 * way (or begun last) — its number, release and start —, the previous cycle's execution time
 * and whether the task overran. Code inside a block reads its task's as current_task(); the
 * scheduler's task_state is one (plc.task("Fast")).
 */
class task_info {
 public:
  constexpr task_info() noexcept = default;

  /// The task's name ("" outside a task cycle).
  [[nodiscard]] const char* name() const noexcept { return settings_.name; }
  /// The task's place in its application's configuration, from 0 (CODESYS's
  /// __CURRENTTASK.TaskIndex; TwinCAT's GETCURTASKINDEXEX() counts from 1); -1 outside a task
  /// cycle.
  [[nodiscard]] std::int32_t index() const noexcept { return index_; }
  [[nodiscard]] task_kind kind() const noexcept { return settings_.kind; }
  /// 0 (highest) .. 31 (lowest).
  [[nodiscard]] std::uint8_t priority() const noexcept { return settings_.priority; }
  /// The interval of a cyclic task; 0 for a freewheeling or an event task.
  [[nodiscard]] LTIME interval() const noexcept { return settings_.interval; }
  [[nodiscard]] const task_settings& settings() const noexcept { return settings_; }
  [[nodiscard]] const task_statistics& statistics() const noexcept { return statistics_; }

  /// The cycles begun since the tasks were last restarted: during a cycle, its number, from 1
  /// (TwinCAT's CycleCount); cycle n - 1 of model_execution_time.
  [[nodiscard]] std::uint64_t cycle_number() const noexcept { return cycle_number_; }
  /// TRUE during the first cycle since the tasks were last restarted (TwinCAT's FirstCycle).
  [[nodiscard]] bool first_cycle() const noexcept { return cycle_number_ == 1; }
  /// When the cycle under way (or begun last) started, on the scheduler's clock: during the
  /// cycle, the cycle clock's time (cycle_clock::now()).
  [[nodiscard]] LTIME cycle_start() const noexcept { return start_time_; }
  /// When the cycle under way (or begun last) was released: cycle_start() - release_time() is
  /// how late it started (its jitter).
  [[nodiscard]] LTIME release_time() const noexcept { return release_time_; }
  /// How long the last cycle that ended took, from its start to its end, including the time
  /// higher-priority tasks took from it (TwinCAT's LastExecTime, CODESYS's dwCycleTime): during
  /// a cycle, the previous cycle's; 0 before one ended. reset_statistics() leaves it.
  [[nodiscard]] LTIME last_exec_time() const noexcept { return last_exec_time_; }
  /// TRUE if a release of the task was skipped (an overrun, counted in statistics().overruns)
  /// between the start of its previous cycle and the start of the cycle under way (or begun
  /// last): the previous cycle, or the wait for this one, took longer than the interval
  /// (TwinCAT's CycleTimeExceeded).
  [[nodiscard]] bool overran() const noexcept { return overran_; }

 protected:
  friend struct detail::task_info_driver;

  // A cycle starts at `now`: what every driver of a task records.
  constexpr void record_begin(LTIME now) noexcept {
    start_time_ = now;
    ++cycle_number_;
    overran_ = overrun_pending_;
    overrun_pending_ = false;
  }
  // The cycle under way ends at `now`: its time is recorded, and returned.
  constexpr LTIME record_end(LTIME now) noexcept {
    const LTIME cycle_time = now - start_time_;
    last_exec_time_ = cycle_time;
    statistics_.record(start_time_ - release_time_, cycle_time);
    return cycle_time;
  }
  // `missed` releases of the task are skipped: overruns.
  constexpr void record_overruns(std::uint64_t missed) noexcept {
    statistics_.overruns += missed;
    statistics_.consecutive_overruns += static_cast<std::uint32_t>(missed);
    overrun_pending_ = true;
  }

  task_settings settings_{};
  task_statistics statistics_{};
  LTIME release_time_{};
  LTIME start_time_{};
  LTIME last_exec_time_{};
  std::uint64_t cycle_number_ = 0;
  // Two bytes (a scheduler has at most 32767 tasks), so that the scheduler's four one-byte
  // members of task_state fill the four bytes up to the next multiple of 8.
  std::int16_t index_ = -1;
  bool overran_ = false;          // a release was skipped between the last two cycles' starts
  bool overrun_pending_ = false;  // one was skipped since the last cycle's start
};

namespace detail {

/// What current_task() gives outside a task cycle: index -1, name "", nothing counted (a
/// constant, in read-only memory).
inline constexpr task_info no_task{};

// The task whose cycle runs now is the fault context's cycle_task (fault.hpp): a task cycle
// makes its task's context current, and with it the task, in one store. nullptr outside a
// task cycle.
[[nodiscard]] inline const task_info* cycle_task() noexcept { return current_fault_context->cycle_task; }

/// For a driver of cycles without a scheduler (the test kit's testing::cycles): a task of its
/// own, whose cycles it records as the scheduler records its tasks'.
struct task_info_driver {
  /// `task` is the task `settings`, the only one of its configuration (index 0).
  static constexpr void configure(task_info& task, const task_settings& settings) noexcept {
    task.settings_ = settings;
    task.index_ = 0;
  }
  /// A cycle released and started at `now`.
  static constexpr void begin(task_info& task, LTIME now) noexcept {
    task.release_time_ = now;
    task.record_begin(now);
  }
  /// The cycle ends at `now`.
  static constexpr void end(task_info& task, LTIME now) noexcept { (void)task.record_end(now); }
};

}  // namespace detail

/**
 * The task whose cycle runs the calling code (see task_info); outside a task cycle, a "no
 * task": index() -1, name() "", interval() 0, cycle_number() 0, priority() 31.
 */
[[nodiscard]] inline const task_info& current_task() noexcept {
  const task_info* const task = detail::cycle_task();
  return task != nullptr ? *task : detail::no_task;
}

/**
 * TwinCAT's PlcTaskSystemInfo (Tc2_System): the fields iecoop's scheduler knows, in TwinCAT's
 * types and units. Times are UDINT multiples of 100 ns, up to 16#FFFFFFFF (429.4967295 s,
 * where they stop). ObjId, AdsPort, DcTaskTime, InCallAfterOutputUpdate and RTViolation have
 * no counterpart.
 */
struct PlcTaskSystemInfo {
  UDINT CycleTime;         ///< the task's interval (0 for a freewheeling or event task)
  UINT Priority;           ///< the task's priority, 0 (highest) .. 31
  UDINT CycleCount;        ///< this cycle's number, from 1 (wraps after 16#FFFFFFFF)
  UDINT LastExecTime;      ///< the previous cycle's time from its start to its end
  BOOL FirstCycle;         ///< TRUE in the first cycle since the tasks were (re)started
  BOOL CycleTimeExceeded;  ///< a release was skipped since the previous cycle began (overran())
  STRING<63> TaskName;     ///< the task's name (its first 63 characters)
};

namespace detail {
// A duration in TwinCAT's UDINT multiples of 100 ns, stopping at 16#FFFFFFFF. Not inlined:
// F_GetTaskInfo() converts two durations, and on a 32-bit core each inlined division by the
// reciprocal is some 40 bytes of flash.
[[nodiscard, gnu::noinline]] constexpr UDINT hundreds_of_ns(LTIME t) noexcept {
  const std::uint64_t n = divide_by<100>(t.count());  // no 64-bit division on a 32-bit core
  return UDINT(static_cast<std::uint32_t>(n > 0xFFFFFFFFU ? 0xFFFFFFFFU : n));
}
}  // namespace detail

/// TwinCAT's F_GetTaskInfo() — `_TaskInfo[GETCURTASKINDEXEX()]`: the current task's
/// PlcTaskSystemInfo (current_task() in TwinCAT's units). Outside a task cycle: Priority 31,
/// the other numbers 0, FALSE and ''.
// The "no task" written out rather than read from detail::no_task: an image that calls
// F_GetTaskInfo() and GETCURTASKINDEXEX() but not current_task() keeps no task_info constant
// (168 bytes of flash on a 32-bit core; docs/embedded.md, "Sizes").
[[nodiscard]] inline PlcTaskSystemInfo F_GetTaskInfo() noexcept {
  const task_info* const task = detail::cycle_task();
  if (task == nullptr) {  // no_task's: a task_settings' priority, the rest 0
    return PlcTaskSystemInfo{UDINT(0U), UINT(task_settings{}.priority), UDINT(0U), UDINT(0U), FALSE, FALSE, {}};
  }
  return PlcTaskSystemInfo{
      detail::hundreds_of_ns(task->interval()),
      UINT(task->priority()),
      UDINT(static_cast<std::uint32_t>(task->cycle_number())),
      detail::hundreds_of_ns(task->last_exec_time()),
      BOOL(task->first_cycle()),
      BOOL(task->overran()),
      STRING<63>(task->name()),
  };
}

/// TwinCAT's GETCURTASKINDEXEX(): the current task's index counting from 1 (the index of
/// `_TaskInfo[]`), or 0 outside a task cycle (TwinCAT's answer in FB_init).
[[nodiscard]] inline DINT GETCURTASKINDEXEX() noexcept {
  const task_info* const task = detail::cycle_task();
  return DINT(task != nullptr ? task->index() + 1 : 0);
}

}  // namespace iecoop

#include <iecoop/detail/pop_macros.hpp>
