// An application running in real time in a thread of its own, for the data exchange's tests:
// the network threads and the task cycles run concurrently, as on a controller.
#pragma once

#include <atomic>
#include <thread>

#include <iecoop/runtime/realtime.hpp>

namespace exchange_test {

/// Runs `app` (started) with a realtime_runner in a thread until stop() or destruction. Read
/// the programs' variables only after stop(): the cycles write them.
template <class App>
class running {
 public:
  explicit running(App& app)
      : thread_([&app, this] {
          iecoop::realtime_runner runner{app};
          runner.run(stop_);
        }) {}
  running(const running&) = delete;
  running& operator=(const running&) = delete;
  ~running() { stop(); }

  void stop() {
    stop_.store(true);
    if (thread_.joinable()) thread_.join();
  }

 private:
  std::atomic<bool> stop_{false};
  std::thread thread_;
};

}  // namespace exchange_test
