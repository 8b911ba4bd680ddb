// SPDX-License-Identifier: MIT
// iecoop/runtime/cycle_observer.hpp — something that looks at a task's variables once per cycle of
// the task, right after its programs ran: a trace recorder (<iecoop/trace.hpp>) or a watch list
// (<iecoop/trace/watch.hpp>), as CODESYS samples a trace in the task the trace names; and,
// optionally, also right before they run: the test kit's forced values (<iecoop/testing.hpp>),
// which CODESYS writes at the start and the end of each cycle.
//
//     plc.task("Fast").attach(recorder.observer());   // what trace_recorder::attach does
//
// Observers are linked into the task's list through themselves (no heap), in the order they
// were attached, and unlink themselves when destroyed; a task that ends first (its
// application is destroyed) unlinks them too, so either may go first.
// IWYU pragma: private, include <iecoop/runtime/scheduler.hpp>
#pragma once

#include <cstdint>

#include <iecoop/config.hpp>
#include <iecoop/types/time.hpp>

#include <iecoop/detail/push_macros.hpp>

namespace iecoop {

namespace detail {
class cycle_observer_list;
}

/**
 * A callback a task makes once per cycle, after the cycle's programs ran and before the
 * outputs they changed are staged for the cycle's end: `notify(self, cycle_start, cycle)` with
 * the cycle clock's time (the cycle's start) and the cycle's number (0 for the first since the
 * tasks were last restarted); and, if given, `before(self, cycle_start, cycle)` after the
 * inputs were latched and before the programs run. Not copyable or movable: the task holds its
 * address.
 */
class cycle_observer {
 public:
  using function = void (*)(cycle_observer& self, LTIME cycle_start, std::uint64_t cycle);

  explicit constexpr cycle_observer(function notify, function before = nullptr) noexcept
      : notify_(notify), before_(before) {}
  cycle_observer(const cycle_observer&) = delete;
  cycle_observer& operator=(const cycle_observer&) = delete;
  ~cycle_observer() { detach(); }

  /// TRUE while linked into a task.
  [[nodiscard]] bool attached() const noexcept { return link_ != nullptr; }

  /// Leaves the task it is attached to (if any).
  void detach() noexcept {
    if (link_ == nullptr) return;
    *link_ = next_;
    if (next_ != nullptr) next_->link_ = link_;
    link_ = nullptr;
    next_ = nullptr;
  }

 private:
  friend class detail::cycle_observer_list;

  function notify_;
  function before_;
  cycle_observer* next_ = nullptr;
  cycle_observer** link_ = nullptr;  // the pointer that points at this observer
};

namespace detail {

/// A task's observers, in the order they were attached.
class cycle_observer_list {
 public:
  constexpr cycle_observer_list() noexcept = default;
  cycle_observer_list(const cycle_observer_list&) = delete;
  cycle_observer_list& operator=(const cycle_observer_list&) = delete;
  ~cycle_observer_list() {
    while (head_ != nullptr) head_->detach();
  }

  /// Appends `observer` (detached from any other task first).
  void attach(cycle_observer& observer) noexcept {
    observer.detach();
    cycle_observer** link = &head_;
    while (*link != nullptr) link = &(*link)->next_;
    *link = &observer;
    observer.link_ = link;
  }

  /// After the programs: every observer's notify.
  void notify(LTIME cycle_start, std::uint64_t cycle) const {
    for (cycle_observer* o = head_; o != nullptr;) {
      cycle_observer* const next = o->next_;  // an observer may detach itself
      o->notify_(*o, cycle_start, cycle);
      o = next;
    }
  }

  /// Before the programs: the observers that have a `before`.
  void notify_before(LTIME cycle_start, std::uint64_t cycle) const {
    for (cycle_observer* o = head_; o != nullptr;) {
      cycle_observer* const next = o->next_;
      if (o->before_ != nullptr) o->before_(*o, cycle_start, cycle);
      o = next;
    }
  }

  [[nodiscard]] bool empty() const noexcept { return head_ == nullptr; }

 private:
  cycle_observer* head_ = nullptr;
};

}  // namespace detail

}  // namespace iecoop

#include <iecoop/detail/pop_macros.hpp>
