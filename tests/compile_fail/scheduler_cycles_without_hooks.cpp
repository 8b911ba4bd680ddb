// EXPECT: iecoop: a scheduler's Cycles type does a task cycle's work; give it begin_cycle
// A scheduler calls its Cycles when a task cycle begins and ends; a type without those
// member functions cannot carry out cycles.
#include <iecoop/runtime/scheduler.hpp>

#include <array>
#include <cstddef>

using namespace iecoop;
struct counting_cycles {
  unsigned begun = 0;
#ifndef IECOOP_COMPILE_FAIL
  void begin_cycle(std::size_t, LTIME) { ++begun; }
  void end_cycle(std::size_t, LTIME) {}
#endif
};
int main() {
  task_settings main_task{};
  main_task.interval = LTIME(TIME(10));
  scheduler<1, counting_cycles> tasks{{main_task}};
  tasks.start();
  tasks.run_until(LTIME(TIME(100)));
  return 0;
}
