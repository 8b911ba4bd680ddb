// SPDX-License-Identifier: MIT
// iecoop/detail/ready_queues.hpp — the scheduler's ready queues: which task gets the
// processor next, in O(1).
// IWYU pragma: private, include <iecoop/runtime/application.hpp>
#pragma once

#include <array>
#include <bit>
#include <cstddef>
#include <cstdint>

namespace iecoop::detail {

/**
 * The busy tasks of an application of N tasks, by priority (0 highest .. 31): at each
 * priority the cycle under way (at most one: a task never preempts one of its own priority)
 * and a queue of released tasks in dispatch order, plus a mask of the priorities that have
 * either. pick() is then the lowest set bit of the mask and its cycle under way or its
 * queue's head — where a scan of all tasks per dispatch made an instant at which N tasks
 * are due cost O(N^2).
 */
template <std::size_t N>
class ready_queues {
 public:
  static constexpr std::size_t none = N;
  static constexpr std::size_t levels = 32;

  /// The task to run: the highest busy priority's cycle under way, else its first released
  /// task; none if nothing is busy.
  [[nodiscard]] std::size_t pick() const noexcept {
    if (busy_ == 0) return none;
    const auto p = static_cast<std::size_t>(std::countr_zero(busy_));
    return active_[p] != none ? active_[p] : head_[p];
  }

  /// Queues `task` at `priority`, after the released tasks that come before it by
  /// `before(a, b)` (release time, then configuration order). Releases arrive nearly
  /// always in that order, so this is an append.
  template <class Before>
  void release(std::size_t task, std::uint8_t priority, Before before) noexcept {
    const std::size_t p = priority;
    next_[task] = none;
    if (head_[p] == none) {
      head_[p] = tail_[p] = task;
    } else if (before(tail_[p], task)) {
      next_[tail_[p]] = task;
      tail_[p] = task;
    } else if (before(task, head_[p])) {
      next_[task] = head_[p];
      head_[p] = task;
    } else {
      std::size_t at = head_[p];
      while (next_[at] != none && before(next_[at], task)) at = next_[at];
      next_[task] = next_[at];
      next_[at] = task;
    }
    busy_ |= bit(p);
  }

  /// The head of `priority`'s queue starts its cycle.
  void begin(std::size_t task, std::uint8_t priority) noexcept {
    const std::size_t p = priority;
    if (head_[p] == task) {
      head_[p] = next_[task];
      if (head_[p] == none) tail_[p] = none;
    }
    active_[p] = task;
    busy_ |= bit(p);
  }

  /// The head of `priority`'s queue, which has no cycle under way, runs a cycle that begins
  /// and ends at once: begin() and end() in one.
  void begin_and_end(std::size_t task, std::uint8_t priority) noexcept {
    const std::size_t p = priority;
    head_[p] = next_[task];
    if (head_[p] == none) {
      tail_[p] = none;
      busy_ &= ~bit(p);
    }
  }

  /// The cycle under way at `priority` ends.
  void end(std::uint8_t priority) noexcept {
    const std::size_t p = priority;
    active_[p] = none;
    if (head_[p] == none) busy_ &= ~bit(p);
  }

  void clear() noexcept { *this = ready_queues{}; }

 private:
  static constexpr std::uint32_t bit(std::size_t p) noexcept { return std::uint32_t{1} << p; }
  static constexpr std::array<std::size_t, levels> empty() noexcept {
    std::array<std::size_t, levels> a{};
    a.fill(none);
    return a;
  }

  std::array<std::size_t, levels> head_ = empty();
  std::array<std::size_t, levels> tail_ = empty();
  std::array<std::size_t, levels> active_ = empty();
  std::array<std::size_t, N> next_{};
  std::uint32_t busy_ = 0;
};

}  // namespace iecoop::detail
