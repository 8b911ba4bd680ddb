// SPDX-License-Identifier: MIT
// iecoop/detail/ready_queues.hpp — the scheduler's ready queues: which task gets the
// processor next, in O(1).
// IWYU pragma: private, include <iecoop/runtime/application.hpp>
#pragma once

#include <array>
#include <bit>
#include <cstddef>
#include <cstdint>
#include <type_traits>

namespace iecoop::detail {

/// Whether a scheduler of N tasks driving `Cycles` finds the task to run by looking at each of
/// its tasks (N <= 4) instead of keeping ready queues: for so few tasks as fast, and the queues'
/// code is most of the dispatch's flash on a small core (456 bytes of the three-task firmware
/// example on a Cortex-M3). A test may specialise it to run the queues with few tasks.
template <std::size_t N, class Cycles>
inline constexpr bool pick_by_scan = N <= 4;

/// The ready queues of a scheduler that picks by looking at its tasks: nothing to keep.
struct no_ready_queues {
  template <class Before>
  void release(std::size_t, std::size_t, Before) noexcept {}
  void begin(std::size_t, std::size_t) noexcept {}
  void begin_and_end(std::size_t, std::size_t) noexcept {}
  void end(std::size_t) noexcept {}
  void clear() noexcept {}
};

/// The level of `priority` (0 highest .. 31) among the priorities whose bits `present` has:
/// how many of them are higher (ready_queues keeps one queue per level).
[[nodiscard]] constexpr std::size_t priority_level(std::uint32_t present, std::uint8_t priority) noexcept {
  const std::uint32_t higher = priority >= 32 ? present : present & ((std::uint32_t{1} << priority) - 1U);
  return static_cast<std::size_t>(std::popcount(higher));
}

/**
 * The busy tasks of an application of N tasks, by level: a level is a priority the tasks
 * have, ranked (level 0 is the highest priority any task has, level 1 the next, ...; see
 * priority_level), so that there are at most N of them, never the 32 priorities. At each
 * level the cycle under way (at most one: a task never preempts one of its own priority) and
 * a queue of released tasks in dispatch order, plus a mask of the levels that have either.
 * pick() is then the lowest set bit of the mask and its cycle under way or its queue's head —
 * where a scan of all tasks per dispatch made an instant at which N tasks are due cost
 * O(N^2). Tasks are kept as the smallest unsigned type that holds N: the queues of three
 * tasks take 16 bytes (400 with a queue per priority and std::size_t indices, on a 32-bit core).
 */
/// The smallest unsigned type that holds the indices 0..N of N tasks (N meaning none).
template <std::size_t N>
using task_index_t =
    std::conditional_t<(N < 0xFFU), std::uint8_t, std::conditional_t<(N < 0xFFFFU), std::uint16_t, std::size_t>>;

template <std::size_t N>
class ready_queues {
  using index_type = task_index_t<N>;

 public:
  static constexpr std::size_t none = N;
  static constexpr std::size_t levels = N < 32 ? N : 32;

  /// The task to run: the highest busy priority's cycle under way, else its first released
  /// task; none if nothing is busy.
  [[nodiscard]] std::size_t pick() const noexcept {
    if (busy_ == 0) return none;
    const auto p = static_cast<std::size_t>(std::countr_zero(busy_));
    return active_[p] != nil ? active_[p] : head_[p];
  }

  /// Queues `task` at `level`, after the released tasks that come before it by
  /// `before(a, b)` (release time, then configuration order). Releases arrive nearly
  /// always in that order, so this is an append.
  template <class Before>
  void release(std::size_t task, std::size_t level, Before before) noexcept {
    const std::size_t p = level;
    const auto t = static_cast<index_type>(task);
    next_[task] = nil;
    if (head_[p] == nil) {
      head_[p] = tail_[p] = t;
    } else if (before(tail_[p], task)) {
      next_[tail_[p]] = t;
      tail_[p] = t;
    } else if (before(task, head_[p])) {
      next_[task] = head_[p];
      head_[p] = t;
    } else {
      std::size_t at = head_[p];
      while (next_[at] != nil && before(next_[at], task)) at = next_[at];
      next_[task] = next_[at];
      next_[at] = t;
    }
    busy_ |= bit(p);
  }

  /// The head of `level`'s queue starts its cycle.
  void begin(std::size_t task, std::size_t level) noexcept {
    const std::size_t p = level;
    if (head_[p] == task) {
      head_[p] = next_[task];
      if (head_[p] == nil) tail_[p] = nil;
    }
    active_[p] = static_cast<index_type>(task);
    busy_ |= bit(p);
  }

  /// The head of `level`'s queue, which has no cycle under way, runs a cycle that begins
  /// and ends at once: begin() and end() in one.
  void begin_and_end(std::size_t task, std::size_t level) noexcept {
    const std::size_t p = level;
    head_[p] = next_[task];
    if (head_[p] == nil) {
      tail_[p] = nil;
      busy_ &= ~bit(p);
    }
  }

  /// The cycle under way at `level` ends.
  void end(std::size_t level) noexcept {
    const std::size_t p = level;
    active_[p] = nil;
    if (head_[p] == nil) busy_ &= ~bit(p);
  }

  void clear() noexcept { *this = ready_queues{}; }

 private:
  static constexpr auto nil = static_cast<index_type>(none);
  static constexpr std::uint32_t bit(std::size_t p) noexcept { return std::uint32_t{1} << p; }
  static constexpr std::array<index_type, levels> empty() noexcept {
    std::array<index_type, levels> a{};
    a.fill(nil);
    return a;
  }

  std::array<index_type, levels> head_ = empty();
  std::array<index_type, levels> tail_ = empty();
  std::array<index_type, levels> active_ = empty();
  std::array<index_type, N> next_{};
  std::uint32_t busy_ = 0;
};

}  // namespace iecoop::detail
