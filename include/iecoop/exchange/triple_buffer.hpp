// SPDX-License-Identifier: MIT
// iecoop/exchange/triple_buffer.hpp — hands a snapshot from one thread to another without locks:
// the producer fills its slot and publishes it, the consumer takes the newest published one.
// Neither side ever waits for the other, and the consumer never sees a half-written snapshot:
// how the data exchange (<iecoop/exchange/modbus_server.hpp>, ...) moves process data between a
// task's cycle and a network thread without letting the network delay the cycle.
//
//     triple_buffer<std::array<std::byte, 64>> box;
//     // producer (one thread):                  // consumer (one other thread):
//     box.write_slot() = data;                   if (box.refresh()) use(box.read_slot());
//     box.publish();
//
// One producer and one consumer. Three slots: the producer's, the consumer's and the one in
// between, exchanged atomically (a flag in the exchanged index tells that it is new). No heap,
// no system calls: it works on a microcontroller between an interrupt and the main loop too.
#pragma once

#include <array>
#include <atomic>
#include <cstdint>

#include <iecoop/config.hpp>

#include <iecoop/detail/push_macros.hpp>

namespace iecoop {

/**
 * Three slots of T passed between one producer and one consumer, lock-free and wait-free.
 * The producer writes write_slot() and calls publish(); the consumer calls refresh() and reads
 * read_slot(), which stays as it is until its next refresh(). All slots start as `initial`.
 */
template <class T>
class triple_buffer {
 public:
  constexpr triple_buffer() = default;
  explicit constexpr triple_buffer(const T& initial) : slots_{initial, initial, initial} {}
  triple_buffer(const triple_buffer&) = delete;
  triple_buffer& operator=(const triple_buffer&) = delete;

  /// Producer: the slot to fill. After publish() it is another slot, holding an older
  /// snapshot (not the one just published): write every part the consumer reads.
  [[nodiscard]] T& write_slot() noexcept { return slots_[write_]; }

  /// Producer: makes the written slot the newest snapshot.
  void publish() noexcept {
    write_ = static_cast<std::uint8_t>(
        middle_.exchange(static_cast<std::uint8_t>(write_ | fresh), std::memory_order_acq_rel) & index_mask);
  }

  /// Consumer: takes the newest snapshot if one was published since the last refresh();
  /// TRUE if it did.
  bool refresh() noexcept {
    if ((middle_.load(std::memory_order_relaxed) & fresh) == 0) return false;
    read_ = static_cast<std::uint8_t>(middle_.exchange(read_, std::memory_order_acq_rel) & index_mask);
    return true;
  }

  /// Consumer: the snapshot taken by the last refresh() (the initial value before any).
  [[nodiscard]] const T& read_slot() const noexcept { return slots_[read_]; }

 private:
  static constexpr std::uint8_t fresh = 4;
  static constexpr std::uint8_t index_mask = 3;

  std::array<T, 3> slots_{};
  std::uint8_t write_ = 0;               // the producer's
  std::atomic<std::uint8_t> middle_{1};  // the one in between, | fresh when published and not yet taken
  std::uint8_t read_ = 2;                // the consumer's
};

}  // namespace iecoop

#include <iecoop/detail/pop_macros.hpp>
