// SPDX-License-Identifier: MIT
// iecoop/trace/watch.hpp — a watch list, as CODESYS's watch view shows a running controller: named
// values (the channels of <iecoop/trace/channels.hpp>) read after a cycle of a task and shown
// as a table in a terminal, refreshed every interval, by a thread of its own.
//
//     watch_list<32> watch{"T#200ms"_iec};              // a new snapshot at most every 200 ms
//     watch.add_located("GVL_IO", plc.get<GVL_IO>());
//     watch.add_pins("IO_PRG.fbConveyor.tJam", io.fbConveyor.tJam);
//     watch.attach(plc.task("Fast"));
//     watch_display display{watch, stdout, "T#500ms"_iec};  // redraws the table every 500 ms
//     runner.run(stop);                                    // the task runs; the table follows
//
// The task's thread only copies the values into a snapshot (a few nanoseconds per value, no
// lock, no system call, no heap); the display thread formats and prints the newest snapshot.
// Snapshots pass between the two through three buffers whose ownership moves with one atomic
// exchange: neither thread ever waits for the other. For the real-time runner
// (<iecoop/runtime/realtime.hpp>) on Linux and other POSIX systems; not part of
// <iecoop/iecoop.hpp>.
#pragma once

#include <atomic>
#include <condition_variable>
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <mutex>
#include <string_view>
#include <thread>

#include <iecoop/config.hpp>
#include <iecoop/detail/chrono.hpp>  // std::chrono's durations and clocks
#include <iecoop/runtime/cycle_observer.hpp>
#include <iecoop/runtime/scheduler.hpp>
#include <iecoop/trace/channels.hpp>
#include <iecoop/trace/put_text.hpp>
#include <iecoop/trace/view.hpp>
#include <iecoop/types/literal_text.hpp>
#include <iecoop/types/time.hpp>

#include <iecoop/detail/push_macros.hpp>

namespace iecoop {

/**
 * A watch list of up to MaxChannels values (add, add_pins, add_located), sampled after a
 * cycle of the task it is attached to, at most once per `interval` of the cycle clock. Any
 * thread may read the newest snapshot (snapshot(), write_table()); only one at a time.
 */
template <std::size_t MaxChannels = 32>
class watch_list : public trace_channels<MaxChannels>, private cycle_observer {
 public:
  explicit watch_list(LTIME interval = LTIME::from_ticks(100'000'000)) noexcept
      : cycle_observer([](cycle_observer& self, LTIME cycle_start, std::uint64_t cycle) {
          static_cast<watch_list&>(self).on_cycle(cycle_start, cycle);
        }),
        interval_(interval) {}

  /// Samples `task` (after its cycles' programs); the channels are fixed while attached.
  void attach(task_state& task) noexcept {
    task.attach(*this);
    this->lock_channels(true);
  }
  void detach() noexcept {
    cycle_observer::detach();
    this->lock_channels(false);
  }
  [[nodiscard]] bool attached() const noexcept { return cycle_observer::attached(); }

  /// The newest snapshot's values, time and cycle, as a one-sample trace_view over the
  /// channels; empty before the first. Call it from one reader thread at a time.
  [[nodiscard]] trace_view snapshot() {
    const std::uint8_t middle = middle_.load(std::memory_order_acquire);
    if ((middle & fresh) != 0) front_ = middle_.exchange(front_, std::memory_order_acq_rel) & index_mask;
    const slot& s = slots_[front_];
    if (!s.valid) return trace_view{};
    return trace_view(this->channels(), s.bytes, 1, sample_bytes(), 0, 1, trace_view::no_trigger, s.cycle);
  }

  /// Writes the newest snapshot as a table (name, type, value as ST writes it) through
  /// `put(std::string_view)`; `title` heads it.
  template <class Put>
  void write_table(Put&& put, std::string_view title = "iecoop watch") {
    const trace_view view = snapshot();
    std::size_t width = 10;
    for (const trace_channel& channel : this->channels()) {
      const std::size_t n =
          channel.scope.empty() ? channel.name.size() : channel.scope.size() + 1 + channel.name.size();
      if (n > width) width = n;
    }
    put(title);
    if (view.empty()) {
      put(": no cycle yet\n");
      return;
    }
    put(" at ");
    char text[64];
    put(std::string_view(text, static_cast<std::size_t>(to_text(text, view.time(0)) - text)));
    put(", cycle ");
    detail::put_unsigned(put, view.cycle(0));
    put("\n");
    const auto pad = [&](std::size_t n) {
      for (; n > 0; --n) put(" ");
    };
    put("Expression");
    pad(width + 2 - 10);
    put("Type        Value\n");
    for (std::size_t c = 0; c < view.channels().size(); ++c) {
      const trace_channel& channel = view.channels()[c];
      std::size_t n = 0;
      put_channel_name(channel, [&](std::string_view part) {
        put(part);
        n += part.size();
      });
      pad(width + 2 - n);
      put(channel.type->name);
      pad(channel.type->name.size() < 12 ? 12 - channel.type->name.size() : 1);
      put(std::string_view(text, static_cast<std::size_t>(view.text(0, c, text) - text)));
      put("\n");
    }
  }

  /// How often a snapshot is taken (by the cycle clock).
  [[nodiscard]] LTIME interval() const noexcept { return interval_; }
  /// The snapshots taken since construction.
  [[nodiscard]] std::uint64_t snapshots() const noexcept { return taken_.load(std::memory_order_relaxed); }

 private:
  static constexpr std::uint8_t fresh = 0x80;
  static constexpr std::uint8_t index_mask = 0x03;
  static constexpr std::size_t slot_bytes = trace_view::header_bytes + MaxChannels * 8;

  struct slot {
    alignas(8) std::byte bytes[slot_bytes]{};
    std::uint64_t cycle = 0;
    bool valid = false;
  };

  [[nodiscard]] std::size_t sample_bytes() const noexcept { return trace_view::header_bytes + this->values_bytes(); }

  void on_cycle(LTIME cycle_start, std::uint64_t cycle) {
    if (taken_.load(std::memory_order_relaxed) != 0 && cycle_start - last_ < interval_ && cycle_start >= last_) return;
    last_ = cycle_start;
    slot& s = slots_[back_];
    const std::uint64_t ns = cycle_start.count();
    const auto low = static_cast<std::uint32_t>(cycle);
    std::memcpy(s.bytes, &ns, 8);
    std::memcpy(s.bytes + 8, &low, 4);
    this->capture(s.bytes + trace_view::header_bytes);
    s.cycle = cycle;
    s.valid = true;
    back_ = middle_.exchange(static_cast<std::uint8_t>(back_ | fresh), std::memory_order_acq_rel) & index_mask;
    taken_.fetch_add(1, std::memory_order_relaxed);
  }

  LTIME interval_;
  LTIME last_{};
  slot slots_[3]{};
  std::uint8_t back_ = 0;                // the writer's (the task's thread)
  std::atomic<std::uint8_t> middle_{1};  // the newest complete snapshot (with `fresh` until read)
  std::uint8_t front_ = 2;               // the reader's
  std::atomic<std::uint64_t> taken_{0};
};

/**
 * Shows a watch list in a terminal: a thread that redraws its table every `refresh` (from the
 * top left of the screen, with ANSI escape sequences, as a watch view does) until the display
 * is destroyed. The table goes to `out` (stdout, say) in one write per refresh.
 */
template <std::size_t MaxChannels>
class watch_display {
 public:
  watch_display(watch_list<MaxChannels>& watch, std::FILE* out, LTIME refresh = LTIME::from_ticks(500'000'000),
                std::string_view title = "iecoop watch")
      : watch_(watch), out_(out), refresh_(refresh), title_(title), thread_([this] { run(); }) {}
  watch_display(const watch_display&) = delete;
  watch_display& operator=(const watch_display&) = delete;
  ~watch_display() {
    {
      const std::lock_guard<std::mutex> lock(mutex_);
      stop_ = true;
    }
    wake_.notify_one();
    thread_.join();
  }

  /// Redraws the table now (the thread does it every refresh).
  void draw() {
    char buffer[8192];
    std::size_t length = 0;
    const auto put = [&](std::string_view text) {
      for (const char c : text) {
        if (length == sizeof buffer) {
          std::fwrite(buffer, 1, length, out_);
          length = 0;
        }
        buffer[length++] = c;
      }
    };
    put("\x1b[H\x1b[J");  // cursor home, clear to the end of the screen
    watch_.write_table(put, title_);
    std::fwrite(buffer, 1, length, out_);
    std::fflush(out_);
  }

 private:
  void run() {
    std::unique_lock<std::mutex> lock(mutex_);
    while (!stop_) {
      lock.unlock();
      draw();
      lock.lock();
      wake_.wait_for(lock, std::chrono::nanoseconds(static_cast<std::int64_t>(refresh_.count())),
                     [this] { return stop_; });
    }
  }

  watch_list<MaxChannels>& watch_;
  std::FILE* out_;
  LTIME refresh_;
  std::string_view title_;
  std::mutex mutex_;
  std::condition_variable wake_;
  bool stop_ = false;
  std::thread thread_;  // last: starts once everything above is ready
};

}  // namespace iecoop

#include <iecoop/detail/pop_macros.hpp>
