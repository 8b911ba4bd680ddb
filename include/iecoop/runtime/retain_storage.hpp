// SPDX-License-Identifier: MIT
// iecoop/runtime/retain_storage.hpp — the storage seam of the retained data: the
// RetainStorage concept a controller's non-volatile memory implements, its two optional
// extensions (RetainStorageWithPrevious, RetainStorageSetAside), and memory_storage, one in
// RAM (file_storage, <iecoop/runtime/file_storage.hpp>, is one in a file).
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
 * when nothing is stored, it cannot be read or the buffer is too small. Exactly the bytes
 * saved: an image followed by more bytes is damaged (a storage on a fixed-size region, FRAM
 * or a flash sector, keeps the size it saved, or reads it from the image's header). memory_storage and
 * file_storage (<iecoop/runtime/file_storage.hpp>) are two; a firmware writes its own for
 * flash or FRAM.
 */
template <class S>
concept RetainStorage = requires(S& s, std::span<const std::byte> data, std::span<std::byte> buffer) {
  { s.save(data) } -> std::same_as<bool>;
  { s.load(buffer) } -> std::convertible_to<std::size_t>;
};

/**
 * A RetainStorage that also keeps the image before the last save (a second slot, as
 * TwinCAT's Port_851.bootdata-old): `load_previous(buffer)` copies it into `buffer` and
 * returns how many bytes, or 0 when there is none, it cannot be read or the buffer is too
 * small. An application that finds the current image missing or damaged may restore this
 * one instead. A save keeps the image it replaces as the previous one; when there is no
 * current image (none saved yet, or it was set aside), the previous one stays as it is.
 * memory_storage and file_storage have it.
 */
template <class S>
concept RetainStorageWithPrevious = RetainStorage<S> && requires(S& s, std::span<std::byte> buffer) {
  { s.load_previous(buffer) } -> std::convertible_to<std::size_t>;
};

/**
 * A RetainStorage that can set the current image aside: `set_aside()` moves it out of the
 * way of later saves (file_storage: to `<path>.rejected`, replacing an older rejected
 * image), so that an image the application rejected — damaged, or not fitting the program —
 * is kept for diagnosis instead of being overwritten by the next save. Afterwards load()
 * returns 0 until the next save, and load_previous() (if the storage has it) still returns
 * the previous image, which the next save leaves in place. TRUE if no current image is left
 * (also when there was none); FALSE if it could not be moved. memory_storage and
 * file_storage have it.
 */
template <class S>
concept RetainStorageSetAside = RetainStorage<S> && requires(S& s) {
  { s.set_aside() } -> std::same_as<bool>;
};

/**
 * A RetainStorage that tells the size of its current image, `stored_size()` (0 if none), also
 * when load() refuses it for a buffer too small: the application then reports the image as
 * too large for its retain memory (retain_load::too_large) instead of finding nothing.
 */
template <class S>
concept RetainStorageSized = RetainStorage<S> && requires(const S& s) {
  { s.stored_size() } -> std::convertible_to<std::size_t>;
};

/**
 * A RetainStorage in RAM, of at most Capacity bytes per image: for tests, and for firmware
 * that copies it to non-volatile memory itself (or that places it in battery-backed RAM).
 * It holds three images — the current one, the previous one (RetainStorageWithPrevious) and
 * one set aside (RetainStorageSetAside) — in three slots of Capacity bytes. A save writes a
 * slot that holds neither the current nor the set-aside image and then makes it the current
 * one, so a save cut short (a power loss in battery-backed RAM) leaves the current image whole.
 */
template <std::size_t Capacity>
class memory_storage {
 public:
  /// Stores `data`, keeping the image it replaces as the previous one; FALSE (and nothing
  /// changed) if it is larger than Capacity.
  bool save(std::span<const std::byte> data) noexcept {
    if (data.size() > Capacity) return false;
    std::uint8_t slot = 0;
    while (slot == current_ || slot == rejected_ || (slot == previous_ && free_slot_exists())) ++slot;
    if (!data.empty()) std::memcpy(slots_[slot].data(), data.data(), data.size());
    sizes_[slot] = data.size();
    if (current_ != none) previous_ = current_;
    current_ = slot;
    return true;
  }
  /// Copies the current image into `buffer`: its number of bytes, or 0 if nothing is stored
  /// or `buffer` is too small.
  std::size_t load(std::span<std::byte> buffer) const noexcept { return copy(current_, buffer); }
  /// Copies the previous image (the one the last save replaced) as load() copies the current one.
  std::size_t load_previous(std::span<std::byte> buffer) const noexcept { return copy(previous_, buffer); }
  /// Sets the current image aside (replacing the one set aside before): load() returns 0
  /// until the next save, rejected() shows it. Always TRUE.
  bool set_aside() noexcept {
    if (current_ != none) rejected_ = current_;
    current_ = none;
    return true;
  }
  /// The current image's bytes.
  [[nodiscard]] std::span<const std::byte> data() const noexcept { return bytes_of(current_); }
  [[nodiscard]] std::size_t size() const noexcept { return data().size(); }
  /// The same: the size of the current image (what tells the application that an image
  /// load() refused was too large for its retain memory).
  [[nodiscard]] std::size_t stored_size() const noexcept { return size(); }
  /// The previous image's bytes (empty if none).
  [[nodiscard]] std::span<const std::byte> previous() const noexcept { return bytes_of(previous_); }
  /// The bytes of the image last set aside (empty if none).
  [[nodiscard]] std::span<const std::byte> rejected() const noexcept { return bytes_of(rejected_); }
  /// Forgets all three images.
  void clear() noexcept { current_ = previous_ = rejected_ = none; }
  static constexpr std::size_t capacity() noexcept { return Capacity; }

 private:
  static constexpr std::uint8_t none = 3;

  [[nodiscard]] bool free_slot_exists() const noexcept {
    for (std::uint8_t slot = 0; slot < 3; ++slot) {
      if (slot != current_ && slot != previous_ && slot != rejected_) return true;
    }
    return false;
  }
  [[nodiscard]] std::span<const std::byte> bytes_of(std::uint8_t slot) const noexcept {
    if (slot == none) return {};
    return {slots_[slot].data(), sizes_[slot]};
  }
  std::size_t copy(std::uint8_t slot, std::span<std::byte> buffer) const noexcept {
    const std::span<const std::byte> bytes = bytes_of(slot);
    if (bytes.empty() || buffer.size() < bytes.size()) return 0;
    std::memcpy(buffer.data(), bytes.data(), bytes.size());
    return bytes.size();
  }

  std::array<std::array<std::byte, Capacity>, 3> slots_{};
  std::array<std::size_t, 3> sizes_{};
  std::uint8_t current_ = none;
  std::uint8_t previous_ = none;
  std::uint8_t rejected_ = none;
};

}  // namespace iecoop

#include <iecoop/detail/pop_macros.hpp>
