// SPDX-License-Identifier: MIT
// iecoop/trace/recorder.hpp — a trace recorder: named values sampled every cycle of a task (or
// only when one changed) into a ring buffer of fixed size, with a trigger and a pre-trigger
// count, as CODESYS Trace and TwinCAT Scope record them. No heap: the buffer is a member.
//
//     // CODESYS Trace configuration          iecoop
//     //   Task: Fast                          trace_recorder<64 * 1024> trace;   (64 KiB of samples)
//     //   Variables: IO_PRG.tJam.IN, ...      trace.add_pins("IO_PRG.tJam", io.tJam);
//     //   Trigger variable: IO_PRG.bJam       trace.trigger_on(io.bJam, trace_edge::rising,
//     //   Trigger edge: positive                                 /*pre_trigger=*/100);
//     //   Post trigger (samples): 400                            ..., /*post_trigger=*/400);
//     //   Record condition: on change         trace.set_mode(trace_mode::on_change);
//     trace.attach(plc.task("Fast"));
//     trace.start();
//     plc.run_for("T#21s"_iec);
//     write_vcd(trace.view(), out);            // outside the cycle: <iecoop/trace/vcd.hpp>
//
// A sample is the cycle clock's time (8 bytes), the low 32 bits of the cycle number (4
// bytes), one bit per BOOL channel and each other value in its own size: 16 BOOLs and 8 INTs
// take 12 + 2 + 16 = 30 bytes. sample_bytes() says it; capacity() is how many fit.
// IWYU pragma: private, include <iecoop/trace.hpp>
#pragma once

#include <cstddef>
#include <cstdint>
#include <cstring>
#include <span>
#include <type_traits>

#include <iecoop/config.hpp>
#include <iecoop/fault.hpp>
#include <iecoop/runtime/cycle_observer.hpp>
#include <iecoop/runtime/scheduler.hpp>
#include <iecoop/standard/cycle_clock.hpp>
#include <iecoop/trace/channels.hpp>
#include <iecoop/trace/view.hpp>
#include <iecoop/types/elementary.hpp>
#include <iecoop/types/time.hpp>

#include <iecoop/detail/push_macros.hpp>

namespace iecoop {

/// When a recorder stores a sample.
enum class trace_mode : std::uint8_t {
  every_cycle,  ///< every cycle of its task (every call of sample())
  on_change,    ///< only when a value differs from the last stored sample (and at the trigger)
};

/// Which change of a BOOL fires a trigger (CODESYS: Trigger edge).
enum class trace_edge : std::uint8_t {
  rising,   ///< FALSE -> TRUE (positive)
  falling,  ///< TRUE -> FALSE (negative)
  both,     ///< either
};

/// What a recorder is doing.
enum class trace_state : std::uint8_t {
  stopped,    ///< not recording: before start(), after stop()
  recording,  ///< recording; with a trigger, waiting for it (the last pre-trigger samples are kept)
  triggered,  ///< the trigger fired: recording the post-trigger samples
  complete,   ///< the post-trigger samples are in: nothing more is recorded until start()
};

/// The short name of a trace_state.
[[nodiscard]] constexpr const char* to_string(trace_state state) noexcept {
  switch (state) {
    case trace_state::stopped: return "stopped";
    case trace_state::recording: return "recording";
    case trace_state::triggered: return "triggered";
    case trace_state::complete: return "complete";
  }
  return "unknown";
}

/**
 * A trace recorder with `Bytes` bytes of sample memory and up to `MaxChannels` channels
 * (<iecoop/trace/channels.hpp>: add, add_pins, add_located). It samples every cycle of the
 * task it is attached to, or whenever sample() is called; the samples go into a ring
 * buffer, so that without a trigger it holds the newest capacity() samples.
 *
 * With a trigger it keeps the `pre_trigger` samples before the one where the trigger fired,
 * that one, and `post_trigger` samples after it, then stops recording (complete()). Not
 * copyable or movable (a task holds its address); not thread-safe: sample and read it in one
 * thread, or read it only while it does not record.
 */
template <std::size_t Bytes, std::size_t MaxChannels = 64>
class trace_recorder : public trace_channels<MaxChannels>, private cycle_observer {
  static_assert(Bytes >= 64, "iecoop: a trace recorder needs at least 64 bytes of sample memory");

 public:
  /// post_trigger's default: as many samples as the buffer has room for after the trigger.
  static constexpr std::size_t fill_buffer = static_cast<std::size_t>(-1);

  trace_recorder() noexcept
      : cycle_observer([](cycle_observer& self, LTIME cycle_start, std::uint64_t cycle) {
          static_cast<trace_recorder&>(self).sample(cycle_start, cycle);
        }) {}
  ~trace_recorder() = default;

  // --- When -------------------------------------------------------------------------

  /// Samples once per cycle of `task`, after its programs ran (detached from any other task).
  void attach(task_state& task) noexcept { task.attach(*this); }
  /// Samples no more task cycles (sample() still records).
  void detach() noexcept { cycle_observer::detach(); }
  [[nodiscard]] bool attached() const noexcept { return cycle_observer::attached(); }

  /// Every cycle (the default) or on change. Takes effect at the next sample.
  void set_mode(trace_mode mode) noexcept { mode_ = mode; }
  [[nodiscard]] trace_mode mode() const noexcept { return mode_; }

  /// Triggers on an edge of the BOOL `variable` (a variable, a var<>/output<> wrapper, a
  /// located %IX/%QX, a PROPERTY). The first sample compares with the value the variable had at
  /// start(). pre_trigger is clamped to capacity() - 1, post_trigger to the room left after it.
  template <class V>
  void trigger_on(V&& variable, trace_edge edge, std::size_t pre_trigger, std::size_t post_trigger = fill_buffer) {
    static_assert(std::is_lvalue_reference_v<V>,
                  "iecoop: a trace triggers on a variable, not on a value (the value is gone when the trace reads "
                  "it); give a BOOL variable, or use trigger_when for a condition");
    using source = detail::trace_source<std::remove_cvref_t<V>>;
    static_assert(source::supported && std::is_same_v<typename source::value_type, BOOL>,
                  "iecoop: trigger_on takes a BOOL variable; for a condition on other values use trigger_when");
    trigger_ = trigger{};
    if constexpr (source::direct) {
      trigger_.variable = &detail::scalar_access::ref(*source::address(variable));
    } else {
      trigger_.object = &variable;
      trigger_.read = [](const void* object) {
        return static_cast<bool>(source::read(*static_cast<const std::remove_cvref_t<V>*>(object)));
      };
    }
    trigger_.edge = edge;
    trigger_.armed = true;
    pre_trigger_ = pre_trigger;
    post_trigger_ = post_trigger;
  }
  /// Triggers at the first sample where `condition(object)` is TRUE (a function returning
  /// BOOL or bool; a lambda without captures converts to one: `+[](const PRG& p) { ... }`).
  template <class O, class R>
  void trigger_when(O&& object, R (*condition)(const std::remove_cvref_t<O>&), std::size_t pre_trigger,
                    std::size_t post_trigger = fill_buffer) noexcept {
    static_assert(std::is_lvalue_reference_v<O>,
                  "iecoop: a trigger condition reads an object that lives as long as the trace (a program, a "
                  "block, a variable), not a temporary");
    static_assert(std::is_same_v<R, BOOL> || std::is_same_v<R, bool>,
                  "iecoop: a trigger condition returns BOOL (or bool); compare, e.g. `return p.iCount > 5;`");
    using object_type = std::remove_cvref_t<O>;
    trigger_ = trigger{};
    trigger_.object = &object;
    // The condition is kept as a generic function pointer and called as its own type again.
    trigger_.condition = reinterpret_cast<void (*)()>(condition);
    trigger_.call = &call_condition<object_type, R>;
    trigger_.level = true;
    trigger_.armed = true;
    pre_trigger_ = pre_trigger;
    post_trigger_ = post_trigger;
  }
  /// Records without a trigger (the default): the newest samples.
  void no_trigger() noexcept { trigger_ = trigger{}; }
  [[nodiscard]] bool has_trigger() const noexcept { return trigger_.armed; }

  // --- Recording --------------------------------------------------------------------

  /**
   * Clears the buffer and starts recording (the channels are fixed until stop()). FALSE, with
   * fault_kind::invalid_value, if not even one sample fits (too many channels for Bytes).
   */
  bool start() {
    sample_bytes_ = trace_view::header_bytes + this->values_bytes();
    slots_ = Bytes / sample_bytes_;
    if (slots_ < 2) {
      slots_ = 0;
      fault(fault_kind::invalid_value,
            "iecoop: a trace recorder's memory holds not even one sample of its channels; give it more Bytes or "
            "fewer channels");
      return false;
    }
    head_ = count_ = after_trigger_ = 0;
    overwritten_ = 0;
    fired_ = false;
    manual_cycle_ = 0;
    pre_ = pre_trigger_ < capacity() ? pre_trigger_ : capacity() - 1;
    post_ = post_trigger_ < capacity() - 1 - pre_ ? post_trigger_ : capacity() - 1 - pre_;
    previous_trigger_ = trigger_.armed && !trigger_.level && read_trigger();
    state_ = trace_state::recording;
    this->lock_channels(true);
    return true;
  }

  /// Stops recording; the samples stay until the next start().
  void stop() noexcept {
    state_ = trace_state::stopped;
    this->lock_channels(false);
  }

  /**
   * Takes a sample now, as a task cycle does: at the cycle clock's time, with a cycle number
   * counted by the recorder. For a block or program driven without an application.
   */
  void sample() { sample(cycle_clock::now(), manual_cycle_); }

  /// Takes a sample stamped `time` and `cycle` (what a task's cycle does).
  void sample(LTIME time, std::uint64_t cycle) {
    if (state_ != trace_state::recording && state_ != trace_state::triggered) return;
    manual_cycle_ = cycle + 1;
    std::byte* const slot = storage_ + head_ * sample_bytes_;
    const std::uint64_t ns = time.count();
    const auto low = static_cast<std::uint32_t>(cycle);
    std::memcpy(slot, &ns, 8);
    std::memcpy(slot + 8, &low, 4);
    this->capture(slot + trace_view::header_bytes);

    bool fire = false;
    if (state_ == trace_state::recording && trigger_.armed) fire = trigger_fires();
    if (mode_ == trace_mode::on_change && count_ > 0 && !fire) {
      const std::byte* const last = storage_ + (head_ == 0 ? slots_ - 1 : head_ - 1) * sample_bytes_;
      if (std::memcmp(slot + trace_view::header_bytes, last + trace_view::header_bytes,
                      sample_bytes_ - trace_view::header_bytes) == 0) {
        return;
      }
    }
    head_ = head_ + 1 == slots_ ? 0 : head_ + 1;
    if (count_ < capacity()) {
      ++count_;
    } else {
      ++overwritten_;
    }
    newest_cycle_ = cycle;
    if (fire) {
      fired_ = true;
      if (count_ > pre_ + 1) count_ = pre_ + 1;
      state_ = post_ == 0 ? trace_state::complete : trace_state::triggered;
      after_trigger_ = 0;
    } else if (state_ == trace_state::triggered && ++after_trigger_ >= post_) {
      state_ = trace_state::complete;
    }
  }

  // --- Results ----------------------------------------------------------------------

  [[nodiscard]] trace_state state() const noexcept { return state_; }
  [[nodiscard]] bool complete() const noexcept { return state_ == trace_state::complete; }
  /// TRUE once the trigger fired (since start()).
  [[nodiscard]] bool triggered() const noexcept { return fired_; }
  /// The samples held.
  [[nodiscard]] std::size_t size() const noexcept { return count_; }
  /// The samples the ring buffer overwrote since start() (the oldest go first): without a
  /// trigger, a recorder that ran longer than its capacity holds only the newest samples.
  [[nodiscard]] std::uint64_t overwritten() const noexcept { return overwritten_; }
  /// The most samples held at once (known from start() on: it depends on the channels).
  [[nodiscard]] std::size_t capacity() const noexcept { return slots_ == 0 ? 0 : slots_ - 1; }
  /// The bytes of one sample (from start() on).
  [[nodiscard]] std::size_t sample_bytes() const noexcept { return sample_bytes_; }
  /// The bytes of sample memory.
  [[nodiscard]] static constexpr std::size_t memory_bytes() noexcept { return Bytes; }

  /// The samples, oldest first, for the writers. Read it while the recorder does not record
  /// (stopped or complete), or between cycles in the thread that samples.
  [[nodiscard]] trace_view view() const noexcept {
    const std::size_t first = slots_ == 0 ? 0 : (head_ + slots_ - count_) % slots_;
    const std::size_t at_trigger = fired_ ? count_ - 1 - after_trigger_ : trace_view::no_trigger;
    return trace_view(this->channels(), storage_, slots_, sample_bytes_, first, count_, at_trigger, newest_cycle_);
  }

 private:
  struct trigger {
    const bool* variable = nullptr;  // a BOOL in memory, or read(object)
    const void* object = nullptr;
    bool (*read)(const void*) = nullptr;
    void (*condition)() = nullptr;  // trigger_when: call(condition, object)
    bool (*call)(void (*)(), const void*) = nullptr;
    trace_edge edge = trace_edge::rising;
    bool level = false;  // trigger_when: fires where the condition holds
    bool armed = false;
  };

  template <class O, class R>
  static bool call_condition(void (*f)(), const void* object) {
    return static_cast<bool>(reinterpret_cast<R (*)(const O&)>(f)(*static_cast<const O*>(object)));
  }

  [[nodiscard]] bool read_trigger() const {
    if (trigger_.level) return trigger_.call(trigger_.condition, trigger_.object);
    return trigger_.variable != nullptr ? *trigger_.variable : trigger_.read(trigger_.object);
  }

  bool trigger_fires() {
    const bool now = read_trigger();
    if (trigger_.level) return now;
    const bool before = previous_trigger_;
    previous_trigger_ = now;
    return trigger_.edge == trace_edge::rising    ? (now && !before)
           : trigger_.edge == trace_edge::falling ? (!now && before)
                                                  : now != before;
  }

  alignas(8) std::byte storage_[Bytes]{};
  std::size_t sample_bytes_ = trace_view::header_bytes;
  std::size_t slots_ = 0;
  std::size_t head_ = 0;   // the slot the next sample goes to (never part of the samples held)
  std::size_t count_ = 0;  // samples held, the newest just before head_
  std::size_t after_trigger_ = 0;
  std::size_t pre_trigger_ = 0;
  std::size_t post_trigger_ = fill_buffer;
  std::size_t pre_ = 0;
  std::size_t post_ = 0;
  std::uint64_t newest_cycle_ = 0;
  std::uint64_t manual_cycle_ = 0;
  std::uint64_t overwritten_ = 0;
  trigger trigger_{};
  bool previous_trigger_ = false;
  bool fired_ = false;
  trace_mode mode_ = trace_mode::every_cycle;
  trace_state state_ = trace_state::stopped;
};

}  // namespace iecoop

#include <iecoop/detail/pop_macros.hpp>
