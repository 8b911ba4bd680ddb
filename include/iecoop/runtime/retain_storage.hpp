// SPDX-License-Identifier: MIT
// iecoop/runtime/retain_storage.hpp — the storage seam of the retained data: the
// RetainStorage concept a controller's non-volatile memory implements, and memory_storage,
// one in RAM (file_storage, <iecoop/runtime/file_storage.hpp>, is one in a file).
#pragma once

#include <array>
#include <concepts>
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <span>

#include <iecoop/config.hpp>

#include <iecoop/detail/push_macros.hpp>

namespace iecoop {

// ---------------------------------------------------------------------------------------
// The storage seam

/**
 * Where a runtime keeps the image between two runs of the program (a controller restart):
 * `save(data)` stores the bytes, replacing what was stored, and returns whether it
 * succeeded; `load(buffer)` copies the stored bytes into `buffer` and returns how many, or 0
 * when nothing is stored or the buffer is too small. memory_storage and file_storage
 * (<iecoop/runtime/file_storage.hpp>) are two; a firmware writes its own for flash or FRAM.
 */
template <class S>
concept RetainStorage = requires(S& s, std::span<const std::byte> data, std::span<std::byte> buffer) {
  { s.save(data) } -> std::same_as<bool>;
  { s.load(buffer) } -> std::convertible_to<std::size_t>;
};

/**
 * A RetainStorage in RAM, of at most Capacity bytes: for tests, and for firmware that copies
 * it to non-volatile memory itself (or that places it in battery-backed RAM).
 */
template <std::size_t Capacity>
class memory_storage {
 public:
  /// Stores `data`; FALSE (and nothing changed) if it is larger than Capacity.
  bool save(std::span<const std::byte> data) noexcept {
    if (data.size() > Capacity) return false;
    if (!data.empty()) std::memcpy(bytes_.data(), data.data(), data.size());
    size_ = data.size();
    return true;
  }
  /// Copies the stored bytes into `buffer`: their number, or 0 if nothing is stored or
  /// `buffer` is too small.
  std::size_t load(std::span<std::byte> buffer) const noexcept {
    if (size_ == 0 || buffer.size() < size_) return 0;
    std::memcpy(buffer.data(), bytes_.data(), size_);
    return size_;
  }
  /// The stored bytes.
  [[nodiscard]] std::span<const std::byte> data() const noexcept { return {bytes_.data(), size_}; }
  [[nodiscard]] std::size_t size() const noexcept { return size_; }
  /// Forgets what is stored.
  void clear() noexcept { size_ = 0; }
  static constexpr std::size_t capacity() noexcept { return Capacity; }

 private:
  std::array<std::byte, Capacity> bytes_{};
  std::size_t size_ = 0;
};

}  // namespace iecoop

#include <iecoop/detail/pop_macros.hpp>
