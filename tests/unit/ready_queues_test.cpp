// The scheduler's ready queues (detail/ready_queues.hpp): the dispatch order of the
// application's pick() — highest priority first; at one priority the cycle under way, then
// the earlier release, then the earlier task in the configuration — kept in O(1) per pick
// whatever order the releases arrive in. The queues are kept by level (the rank of a
// priority among those the tasks have: detail::priority_level), at most one per task.
#include "iecoop_test.hpp"

#include <array>
#include <cstddef>
#include <cstdint>

#include <iecoop/detail/ready_queues.hpp>

namespace {

using queues = iecoop::detail::ready_queues<6>;

// Task i was released at release_time[i]; ties go to the lower index.
struct order {
  const std::array<std::uint64_t, 6>* release_time;
  bool operator()(std::size_t a, std::size_t b) const {
    return (*release_time)[a] < (*release_time)[b] || ((*release_time)[a] == (*release_time)[b] && a < b);
  }
};

}  // namespace

TEST_CASE("ready_queues: nothing busy, then the highest priority first") {
  queues q;
  std::array<std::uint64_t, 6> at{};
  CHECK(q.pick() == queues::none);
  q.release(3, 1, order{&at});
  q.release(1, 0, order{&at});
  q.release(5, 5, order{&at});
  CHECK(q.pick() == 1);
  q.begin(1, 0);
  CHECK(q.pick() == 1);  // under way: still the one to run
  q.end(0);
  CHECK(q.pick() == 3);
  q.begin(3, 1);
  q.end(1);
  CHECK(q.pick() == 5);
  q.begin(5, 5);
  q.end(5);
  CHECK(q.pick() == queues::none);
}

TEST_CASE("ready_queues: at one priority, the cycle under way, then release time, then index") {
  queues q;
  std::array<std::uint64_t, 6> at{5, 5, 5, 5, 5, 5};
  q.release(2, 4, order{&at});
  q.begin(2, 4);
  // Released out of order: 4 (time 5), 0 (time 5: before 4), 3 (time 1: before both),
  // 1 (time 3: between 3 and 0).
  q.release(4, 4, order{&at});
  q.release(0, 4, order{&at});
  at[3] = 1;
  q.release(3, 4, order{&at});
  at[1] = 3;
  q.release(1, 4, order{&at});
  CHECK(q.pick() == 2);
  q.end(4);
  const std::array<std::size_t, 4> expected{3, 1, 0, 4};
  for (const std::size_t task : expected) {
    REQUIRE(q.pick() == task);
    q.begin(task, 4);
    q.end(4);
  }
  CHECK(q.pick() == queues::none);
}

TEST_CASE("ready_queues: a higher priority released meanwhile runs before the preempted cycle") {
  queues q;
  std::array<std::uint64_t, 6> at{};
  q.release(0, 3, order{&at});
  q.begin(0, 3);
  q.release(1, 2, order{&at});
  CHECK(q.pick() == 1);
  q.begin(1, 2);
  q.end(2);
  CHECK(q.pick() == 0);  // the preempted cycle resumes
  q.clear();
  CHECK(q.pick() == queues::none);
}

TEST_CASE("ready_queues: a priority's level is its rank among the priorities present") {
  using iecoop::detail::priority_level;
  const std::uint32_t present = (1U << 0) | (1U << 5) | (1U << 10) | (1U << 31);
  CHECK(priority_level(present, 0) == 0);
  CHECK(priority_level(present, 5) == 1);
  CHECK(priority_level(present, 10) == 2);
  CHECK(priority_level(present, 31) == 3);
  CHECK(priority_level(1U << 31, 31) == 0);  // one task, at the lowest priority
  CHECK(priority_level(0xFFFFFFFFU, 31) == 31);
  static_assert(iecoop::detail::ready_queues<3>::levels == 3);
  static_assert(iecoop::detail::ready_queues<40>::levels == 32);
  // Three tasks' queues: three bytes per level and per link, and the mask.
  static_assert(sizeof(iecoop::detail::ready_queues<3>) == 16);
}
