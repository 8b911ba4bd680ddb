// SPDX-License-Identifier: MIT
// iecoop/runtime/file_storage.hpp — a RetainStorage (<iecoop/runtime/retain.hpp>) in a file: where a PC or
// an embedded Linux keeps its RETAIN and PERSISTENT image between two runs.
//
//     iecoop::file_storage storage{"/var/lib/machine/retain.bin"};
//     storage.save(image);                 // writes retain.bin.tmp, renames it over retain.bin
//     std::size_t n = storage.load(buffer);
//
// Only <cstdio>: no allocation, no exceptions.
#pragma once

#include <cstddef>
#include <cstdio>
#include <span>

#include <iecoop/config.hpp>
#include <iecoop/fault.hpp>

#include <iecoop/detail/push_macros.hpp>

namespace iecoop {

/**
 * A RetainStorage in the file at `path`.
 *
 * save() writes `<path>.tmp` and renames it over `<path>`, so a crash while writing keeps the
 * previous file (on POSIX the rename replaces the file atomically; on Windows, whose rename
 * does not replace an existing file, the old file is removed first, and a crash between the
 * two steps leaves only `<path>.tmp`). The bytes reach the operating system, not
 * necessarily the disk: <cstdio> has no fsync, so a power failure right after save() may
 * lose them. load() of a missing or empty file, or of a file larger than the buffer,
 * returns 0.
 *
 * The path is copied (at most max_path characters; a longer one reports
 * fault_kind::invalid_value, and the storage then saves and loads nothing).
 */
class file_storage {
 public:
  static constexpr std::size_t max_path = 255;

  explicit file_storage(const char* path) noexcept {
    std::size_t n = 0;
    while (path != nullptr && path[n] != '\0' && n <= max_path) ++n;
    if (path == nullptr || n == 0 || n > max_path) {
      fault(fault_kind::invalid_value, "file_storage needs a path of 1 to 255 characters");
      return;
    }
    for (std::size_t i = 0; i < n; ++i) path_[i] = path[i];
    path_[n] = '\0';
    length_ = n;
  }

  /// Replaces the file's contents with `data`; FALSE if a step failed (the previous file,
  /// if any, is then still there, and no `.tmp` is left behind).
  bool save(std::span<const std::byte> data) noexcept {
    if (length_ == 0) return false;
    char temporary[max_path + 5];
    for (std::size_t i = 0; i < length_; ++i) temporary[i] = path_[i];
    const char suffix[] = ".tmp";
    for (std::size_t i = 0; i < sizeof(suffix); ++i) temporary[length_ + i] = suffix[i];

    std::FILE* file = std::fopen(temporary, "wb");
    if (file == nullptr) return false;
    const bool written = data.empty() || std::fwrite(data.data(), 1, data.size(), file) == data.size();
    const bool flushed = std::fflush(file) == 0;
    const bool closed = std::fclose(file) == 0;
    if (!written || !flushed || !closed) {
      std::remove(temporary);
      return false;
    }
    if (std::rename(temporary, path_) == 0) return true;
#if defined(_WIN32)
    // Windows' rename does not replace an existing file: remove it first.
    if (std::remove(path_) == 0 && std::rename(temporary, path_) == 0) return true;
#endif
    std::remove(temporary);
    return false;
  }

  /// Reads the file into `buffer`: the number of bytes, or 0 if there is no such file, it is
  /// empty, it cannot be read, or it is larger than `buffer`.
  std::size_t load(std::span<std::byte> buffer) noexcept {
    if (length_ == 0) return 0;
    std::FILE* file = std::fopen(path_, "rb");
    if (file == nullptr) return 0;
    const std::size_t read = buffer.empty() ? 0 : std::fread(buffer.data(), 1, buffer.size(), file);
    const bool failed = std::ferror(file) != 0;
    const bool more = !failed && std::fgetc(file) != EOF;  // the file is larger than the buffer
    std::fclose(file);
    return failed || more ? 0 : read;
  }

  /// The file's path ("" if the path given was too long).
  [[nodiscard]] const char* path() const noexcept { return path_; }

 private:
  char path_[max_path + 1]{};
  std::size_t length_ = 0;
};

}  // namespace iecoop

#include <iecoop/detail/pop_macros.hpp>
