// SPDX-License-Identifier: MIT
// iecoop/runtime/task_cycles.hpp — what one task cycle of an application does, as the
// scheduler (<iecoop/runtime/scheduler.hpp>) calls it: at the cycle's start the inputs are
// latched from the I/O driver, the cycle clock is set, the task's programs are called in
// order, and the outputs they changed are staged; at its end the staged outputs are merged
// into the published outputs, which go to the driver.
//
// Outputs are diffed per cycle (docs/design.md, "Outputs are diffed per cycle"): the bits a
// cycle changed are its outputs, so two tasks can drive two bits of one byte, and a preempted
// cycle's half-written outputs do not reach the field before its end.
// IWYU pragma: private, include <iecoop/runtime/application.hpp>
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <span>

#include <iecoop/config.hpp>
#include <iecoop/detail/meta.hpp>
#include <iecoop/fault.hpp>
#include <iecoop/io/driver.hpp>
#include <iecoop/runtime/cycle_observer.hpp>
#include <iecoop/runtime/task.hpp>
#include <iecoop/standard/cycle_clock.hpp>
#include <iecoop/types/detail/type_hash.hpp>
#include <iecoop/types/time.hpp>

#include <iecoop/detail/push_macros.hpp>

namespace iecoop::detail {

template <class Store, class Task>
struct task_programs;
template <class Store, class... P>
struct task_programs<Store, task<P...>> {
  // Each program is called with its name in the fault context (a fault names the program).
  static void run(Store& store) {
    fault_context& context = *current_fault_context;  // the task's (the scheduler's scope)
    ((context.pou = short_type_name_c<P>.data(), store.template get<P>()()), ...);
    context.pou = nullptr;
  }
};

/// The cycles of the tasks `Tasks...` (a type_list of task<...>), whose programs live in a
/// `Store` (get<P>()), over the process image `Image`. A TaskCycles for the scheduler.
template <class Image, class Store, class Tasks>
class task_cycles;
template <class Image, class Store, class... Tasks>
class task_cycles<Image, Store, type_list<Tasks...>> {
  static constexpr std::size_t output_bytes = Image::output_bytes;
  static constexpr std::array<void (*)(Store&), sizeof...(Tasks)> programs_of{&task_programs<Store, Tasks>::run...};

 public:
  explicit task_cycles(Store& store) noexcept : store_(store) {}
  task_cycles(const task_cycles&) = delete;
  task_cycles& operator=(const task_cycles&) = delete;

  /// A cycle of task `index` starts: inputs latched, the cycle clock set, the programs
  /// called, the outputs they changed staged for the cycle's end. The task's `observers` are
  /// called right before the programs (notify_before) and right after them (notify).
  void begin_cycle(std::size_t index, LTIME now, const cycle_observer_list& observers, std::uint64_t cycle) {
    if (driver_.read != nullptr) driver_.read(Image::inputs(), driver_.object);
    cycle_clock::set(now);
    if constexpr (output_bytes == 0) {
      run_programs(index, now, observers, cycle);
    } else {
      const auto outputs = Image::outputs();
      std::array<std::byte, output_bytes> before;
      std::memcpy(before.data(), outputs.data(), output_bytes);
      run_programs(index, now, observers, cycle);
      // The bytes the programs changed; most cycles change few, many none: then nothing is
      // staged, and the cycle's end only writes the published outputs again.
      staged_outputs& staged = staged_[index];
      staged.changed = differs(before, outputs);
      if (staged.changed) {
        for (std::size_t b = 0; b < output_bytes; ++b) {
          staged.value[b] = outputs[b];
          staged.mask[b] = before[b] ^ outputs[b];
        }
      }
    }
  }

  /// The cycle of task `index` ends: the outputs it changed are published and written.
  void end_cycle(std::size_t index, LTIME /*now*/) {
    if constexpr (output_bytes > 0) {
      const staged_outputs& staged = staged_[index];
      if (staged.changed) {
        for (std::size_t b = 0; b < output_bytes; ++b) {
          published_[b] = (published_[b] & ~staged.mask[b]) | (staged.value[b] & staged.mask[b]);
        }
      }
    }
    if (driver_.write != nullptr) driver_.write(published_, driver_.object);
  }

  /// Uses `driver` from now on; it must outlive its use.
  template <IoDriver D>
  void connect(D& driver) noexcept {
    driver_.object = &driver;
    driver_.read = [](std::span<std::byte> in, void* d) { static_cast<D*>(d)->read_inputs(in); };
    driver_.write = [](std::span<const std::byte> out, void* d) { static_cast<D*>(d)->write_outputs(out); };
    driver_.check = [](const void* d) noexcept { return configuration_error_of(*static_cast<const D*>(d)); };
  }

  /// The connected driver's configuration_error(): nullptr, or why it must not run.
  [[nodiscard]] const char* io_configuration_error() const noexcept {
    return driver_.check != nullptr ? driver_.check(driver_.object) : nullptr;
  }

  /// The output area as it is now is what goes out with the next cycle's outputs (what the
  /// instances' construction wrote to %Q: FB_Init, a located output's initial value).
  void publish_image_outputs() noexcept {
    if constexpr (output_bytes > 0) std::memcpy(published_.data(), Image::outputs().data(), output_bytes);
  }

  /// The outputs as last written to the driver (what the field sees).
  [[nodiscard]] std::span<const std::byte, output_bytes> published() const noexcept { return published_; }

 private:
  // The outputs one cycle changed, to be written at its end.
  struct staged_outputs {
    std::array<std::byte, output_bytes> value{};
    std::array<std::byte, output_bytes> mask{};
    bool changed = false;  // some bit of mask is set
  };

  // The programs of task `index`, between the observers' two calls when it has observers; a
  // task that nobody observes pays one test for them.
  void run_programs(std::size_t index, LTIME now, const cycle_observer_list& observers, std::uint64_t cycle) {
    if (observers.empty()) [[likely]] {
      programs_of[index](store_);
    } else {
      observers.notify_before(now, cycle);
      programs_of[index](store_);
      observers.notify(now, cycle);
    }
  }

  // Whether the two output areas differ: 8 bytes at a time, then the bytes left (memcmp would
  // be called, or expanded byte by byte).
  static bool differs(const std::array<std::byte, output_bytes>& a,
                      std::span<const std::byte, output_bytes> b) noexcept {
    std::uint64_t any = 0;
    std::size_t i = 0;
    for (; i + 8 <= output_bytes; i += 8) {
      std::uint64_t x;
      std::uint64_t y;
      std::memcpy(&x, a.data() + i, 8);
      std::memcpy(&y, b.data() + i, 8);
      any |= x ^ y;
    }
    for (; i < output_bytes; ++i) any |= static_cast<std::uint64_t>(a[i] ^ b[i]);
    return any != 0;
  }

  Store& store_;
  std::array<staged_outputs, sizeof...(Tasks)> staged_{};
  std::array<std::byte, output_bytes> published_{};
  // The connected driver (without one, nothing is read or written) and its three calls;
  // not a callback_io, whose input windows (an io_chain's) would be 8 bytes more.
  struct driver_binding {
    void* object = nullptr;
    void (*read)(std::span<std::byte>, void*) = nullptr;
    void (*write)(std::span<const std::byte>, void*) = nullptr;
    const char* (*check)(const void*) noexcept = nullptr;  // its configuration_error()
  } driver_{};
};

}  // namespace iecoop::detail

#include <iecoop/detail/pop_macros.hpp>
