// The scheduler's ready queues (detail/ready_queues.hpp): the dispatch order of the
// application's pick() — highest priority first; at one priority the cycle under way, then
// the earlier release, then the earlier task in the configuration — kept in O(1) per pick
// whatever order the releases arrive in.
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
  q.release(3, 10, order{&at});
  q.release(1, 4, order{&at});
  q.release(5, 31, order{&at});
  CHECK(q.pick() == 1);
  q.begin(1, 4);
  CHECK(q.pick() == 1);  // under way: still the one to run
  q.end(4);
  CHECK(q.pick() == 3);
  q.begin(3, 10);
  q.end(10);
  CHECK(q.pick() == 5);
  q.begin(5, 31);
  q.end(31);
  CHECK(q.pick() == queues::none);
}

TEST_CASE("ready_queues: at one priority, the cycle under way, then release time, then index") {
  queues q;
  std::array<std::uint64_t, 6> at{5, 5, 5, 5, 5, 5};
  q.release(2, 7, order{&at});
  q.begin(2, 7);
  // Released out of order: 4 (time 5), 0 (time 5: before 4), 3 (time 1: before both),
  // 1 (time 3: between 3 and 0).
  q.release(4, 7, order{&at});
  q.release(0, 7, order{&at});
  at[3] = 1;
  q.release(3, 7, order{&at});
  at[1] = 3;
  q.release(1, 7, order{&at});
  CHECK(q.pick() == 2);
  q.end(7);
  const std::array<std::size_t, 4> expected{3, 1, 0, 4};
  for (const std::size_t task : expected) {
    REQUIRE(q.pick() == task);
    q.begin(task, 7);
    q.end(7);
  }
  CHECK(q.pick() == queues::none);
}

TEST_CASE("ready_queues: a higher priority released meanwhile runs before the preempted cycle") {
  queues q;
  std::array<std::uint64_t, 6> at{};
  q.release(0, 20, order{&at});
  q.begin(0, 20);
  q.release(1, 2, order{&at});
  CHECK(q.pick() == 1);
  q.begin(1, 2);
  q.end(2);
  CHECK(q.pick() == 0);  // the preempted cycle resumes
  q.clear();
  CHECK(q.pick() == queues::none);
}
