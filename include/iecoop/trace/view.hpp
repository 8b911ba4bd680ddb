// SPDX-License-Identifier: MIT
// iecoop/trace/view.hpp — recorded samples as the writers read them (<iecoop/trace/vcd.hpp>,
// csv.hpp, svg.hpp): the channels, and per sample its time, its cycle and each channel's
// value. A trace recorder (<iecoop/trace/recorder.hpp>) and a watch list's snapshot
// (<iecoop/trace/watch.hpp>) give one.
// IWYU pragma: private, include <iecoop/trace.hpp>
#pragma once

#include <cstddef>
#include <cstdint>
#include <cstring>
#include <span>

#include <iecoop/config.hpp>
#include <iecoop/trace/channels.hpp>
#include <iecoop/types/elementary.hpp>
#include <iecoop/types/literal_text.hpp>
#include <iecoop/types/time.hpp>

#include <iecoop/detail/push_macros.hpp>

namespace iecoop {

/**
 * What a recorder holds, for the writers (<iecoop/trace/vcd.hpp>, csv.hpp, svg.hpp): the
 * channels and the samples, oldest first. Valid while the recorder neither records nor
 * changes; read it outside the cycle (after stop(), or once complete()).
 */
class trace_view {
 public:
  static constexpr std::size_t header_bytes = 12;
  static constexpr std::size_t no_trigger = static_cast<std::size_t>(-1);

  constexpr trace_view() noexcept = default;
  trace_view(std::span<const trace_channel> channels, const std::byte* storage, std::size_t slots,
             std::size_t sample_bytes, std::size_t first, std::size_t count, std::size_t trigger,
             std::uint64_t newest_cycle) noexcept
      : channels_(channels),
        storage_(storage),
        slots_(slots),
        sample_bytes_(sample_bytes),
        first_(first),
        count_(count),
        trigger_(trigger),
        newest_cycle_(newest_cycle) {}

  [[nodiscard]] std::span<const trace_channel> channels() const noexcept { return channels_; }
  /// The number of samples.
  [[nodiscard]] std::size_t size() const noexcept { return count_; }
  [[nodiscard]] bool empty() const noexcept { return count_ == 0; }

  /// The cycle clock's time of sample i (0: the oldest).
  [[nodiscard]] LTIME time(std::size_t i) const noexcept {
    std::uint64_t ns;
    std::memcpy(&ns, at(i), 8);
    return LTIME::from_ticks(ns);
  }
  /// The task cycle of sample i (as task_state::cycle_number() counts, from 0). A sample
  /// keeps the low 32 bits; the rest come from the newest sample's, so two samples kept at
  /// once may lie up to 2^32 cycles apart.
  [[nodiscard]] std::uint64_t cycle(std::size_t i) const noexcept {
    const std::uint32_t newest = low_cycle(count_ - 1);
    return newest_cycle_ - static_cast<std::uint32_t>(newest - low_cycle(i));
  }
  /// The value of channel c in sample i.
  [[nodiscard]] trace_value value(std::size_t i, std::size_t c) const noexcept {
    const trace_channel& channel = channels_[c];
    return detail::decode_trace_value(*channel.type, at(i) + header_bytes, channel.offset);
  }
  /// The IEC text of channel c's value in sample i (`TRUE`, `T#1s500ms`); returns the end.
  /// `out` needs room for channels()[c].type->max_text characters.
  char* text(std::size_t i, std::size_t c, char* out) const {
    const trace_channel& channel = channels_[c];
    if (channel.type->kind == trace_kind::boolean) {
      const BOOL b(value(i, c).u != 0);
      return to_text(out, b);
    }
    return channel.type->text(out, at(i) + header_bytes + channel.offset);
  }
  /// TRUE if channel c holds the same bytes in samples i and j (a NaN is the same NaN; the
  /// bytes, not the values, so that no floating point is needed to compare a REAL).
  [[nodiscard]] bool same_value(std::size_t i, std::size_t j, std::size_t c) const noexcept {
    const trace_channel& channel = channels_[c];
    const std::byte* const a = at(i) + header_bytes;
    const std::byte* const b = at(j) + header_bytes;
    if (channel.type->kind == trace_kind::boolean) {
      const std::byte bit{static_cast<unsigned char>(1U << (channel.offset % 8))};
      return ((a[channel.offset / 8] ^ b[channel.offset / 8]) & bit) == std::byte{0};
    }
    return std::memcmp(a + channel.offset, b + channel.offset, channel.type->bytes) == 0;
  }
  /// TRUE if sample i holds the same values as sample j (they differ only in time).
  [[nodiscard]] bool same_values(std::size_t i, std::size_t j) const noexcept {
    return std::memcmp(at(i) + header_bytes, at(j) + header_bytes, sample_bytes_ - header_bytes) == 0;
  }
  /// The sample at which the trigger fired, or no_trigger.
  [[nodiscard]] std::size_t trigger_index() const noexcept { return trigger_; }

 private:
  [[nodiscard]] const std::byte* at(std::size_t i) const noexcept {
    std::size_t slot = first_ + i;
    if (slot >= slots_) slot -= slots_;
    return storage_ + slot * sample_bytes_;
  }
  [[nodiscard]] std::uint32_t low_cycle(std::size_t i) const noexcept {
    std::uint32_t low;
    std::memcpy(&low, at(i) + 8, 4);
    return low;
  }

  std::span<const trace_channel> channels_{};
  const std::byte* storage_ = nullptr;
  std::size_t slots_ = 0;
  std::size_t sample_bytes_ = 0;
  std::size_t first_ = 0;
  std::size_t count_ = 0;
  std::size_t trigger_ = no_trigger;
  std::uint64_t newest_cycle_ = 0;
};

}  // namespace iecoop

#include <iecoop/detail/pop_macros.hpp>
