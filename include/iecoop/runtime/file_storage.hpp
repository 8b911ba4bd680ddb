// SPDX-License-Identifier: MIT
// iecoop/runtime/file_storage.hpp — a RetainStorage (<iecoop/runtime/retain_storage.hpp>) in a file: where a
// PC or an embedded Linux keeps its RETAIN and PERSISTENT image between two runs.
//
//     iecoop::file_storage storage{"/var/lib/machine/retain.bin"};
//     storage.save(image);                    // a new retain.bin; the one before is retain.bin.previous
//     std::size_t n = storage.load(buffer);   // retain.bin
//     n = storage.load_previous(buffer);      // retain.bin.previous
//     storage.set_aside();                    // retain.bin becomes retain.bin.rejected
//
// On POSIX systems only system calls (open, write, fsync, link, rename, ...): no allocation,
// no exceptions. Elsewhere <cstdio>, which allocates and does not sync (see file_storage).
#pragma once

#include <cstddef>
#include <span>

#if (defined(__unix__) || defined(__APPLE__)) && __has_include(<unistd.h>)
#include <atomic>
#include <cerrno>
#include <cstring>

#include <fcntl.h>
#include <signal.h>
#include <sys/stat.h>
#include <sys/types.h>
#include <unistd.h>
#if defined(__linux__) && __has_include(<dirent.h>)
#include <dirent.h>  // getdents64: a directory's names without opendir's allocation
#endif
#else
#include <cstdio>
#endif

#include <iecoop/config.hpp>
#include <iecoop/fault.hpp>

#include <iecoop/detail/push_macros.hpp>

namespace iecoop {

#if (defined(__unix__) || defined(__APPLE__)) && __has_include(<unistd.h>)
namespace detail {
/// How many temporary names the file_storage objects of this process have taken: the n of its
/// next `<path>.<pid>.<n>.tmp`. One counter for all objects, so that no two saves running in
/// a process use the same name (and the pid tells processes apart).
inline std::atomic<unsigned long> file_storage_names_taken{0};
}  // namespace detail
#endif

/**
 * A RetainStorage in the file at `path`, with the image before the last save kept in
 * `<path>.previous` and an image the application rejected kept in `<path>.rejected`.
 *
 * On POSIX systems (Linux, the BSDs, macOS), save():
 *   1. creates a temporary file `<path>.<pid>.<n>.tmp` in the same directory, exclusively
 *      (O_CREAT | O_EXCL | O_NOFOLLOW: it never opens an existing file nor follows a symbolic
 *      link planted there; on a name that exists it takes the next n), writes the image and
 *      fsyncs it (F_FULLFSYNC on macOS);
 *   2. makes the current `<path>`, if there is one, the previous image: a hard link under a
 *      second unique name, renamed over `<path>.previous` (where the file system has no hard
 *      links, `<path>` itself is renamed to `<path>.previous`);
 *   3. renames the temporary file over `<path>` and fsyncs the directory.
 * Each step replaces names atomically and no file is ever written after it has its final name,
 * so a save cut short at any point (the process killed, the power lost after the file's fsync)
 * leaves `<path>` with the old image or the new one, whole; only where hard links are missing
 * a cut between the two renames leaves no `<path>` and the old image in `<path>.previous`.
 * Two processes (or two file_storage objects) saving to one path never share a temporary
 * file (n counts the names a process took): the last rename wins and each image is whole. A symbolic link at `<path>`,
 * `<path>.previous` or `<path>.rejected` is replaced, never written through. A failed save
 * removes its temporary file; a killed one leaves it behind (`<path>.<pid>.<n>.tmp`, which
 * nothing reads). A file_storage, when it is made (at a program's start), removes those of its
 * path whose process no longer runs (Linux; `removed_temporaries()` says how many): a process
 * that is still running may be saving into its own. The processes that save to one path must
 * see each other's process ids (one PID namespace).
 *
 * An empty `<path>` (a file system that lost the file's data, a tool that truncated it) holds
 * no image: a save then keeps `<path>.previous` as it is rather than making the empty file the
 * previous image, so the last image there was stays reachable.
 *
 * load() and load_previous() read `<path>` and `<path>.previous`: the number of bytes, or 0
 * for a missing, empty or unreadable file, one that is not a regular file, or one larger
 * than the buffer. set_aside() renames `<path>` over `<path>.rejected`: later saves never
 * overwrite that image, load() returns 0 until the next save, load_previous() still returns
 * the previous image, and the save after it keeps that previous image (there is no current
 * one to take its place).
 *
 * Elsewhere (no <unistd.h>: Windows, a bare-metal C library) the same three files are kept
 * through <cstdio>, which allocates, cannot fsync, and writes the fixed temporary file
 * `<path>.tmp` (following a link there; two savers collide): neither durable nor
 * allocation-free nor safe against other users of the directory. A crash between its renames
 * leaves the old image in `<path>.previous` only.
 *
 * The path is copied (at most max_path characters; a longer one reports
 * fault_kind::invalid_value, and the storage then saves and loads nothing). The file's own
 * name must leave room for the suffixes within the system's limit of a name (NAME_MAX, 255
 * on Linux): about 30 characters. Several threads may save through one object, several
 * objects (in one process or in several) to one path.
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
    for (std::size_t i = 0; i < n; ++i) {
      path_[i] = path[i];
      if (path[i] == '/') name_ = i + 1;
    }
    path_[n] = '\0';
    length_ = n;
    removed_temporaries_ = remove_stale_temporaries();
  }

  /// Replaces the image with `data`, keeping the one it replaces as the previous image; FALSE
  /// if a step failed. After a failed save `<path>` holds the image it held (or, where hard
  /// links are missing and only the last rename failed, none, with that image in
  /// `<path>.previous`), and no temporary file is left. FALSE also if the directory could
  /// not be synced at the end: the new image is then in place but may not survive a power
  /// failure.
  bool save(std::span<const std::byte> data) noexcept {
    if (length_ == 0) return false;
    return save_file(data);
  }

  /// Reads `<path>` into `buffer`: the number of bytes, or 0 if there is no such file, it is
  /// empty, it cannot be read, or it is larger than `buffer`.
  std::size_t load(std::span<std::byte> buffer) const noexcept {
    if (length_ == 0) return 0;
    return load_file(path_, buffer);
  }

  /// Reads `<path>.previous`, the image the last save replaced, as load() reads `<path>`.
  std::size_t load_previous(std::span<std::byte> buffer) const noexcept {
    if (length_ == 0) return 0;
    char previous[name_capacity];
    return load_file(with_suffix(previous, 0, previous_suffix), buffer);
  }

  /// Renames `<path>` over `<path>.rejected`, out of reach of later saves (an image the
  /// application found damaged or not fitting its program). TRUE if there is no `<path>`
  /// afterwards (also when there was none); FALSE if it could not be moved.
  bool set_aside() noexcept {
    if (length_ == 0) return false;
    return set_aside_file();
  }

  /// The size of `<path>` in bytes, 0 if there is none (or it is no regular file): what tells
  /// the application that an image load() refused was too large for its retain memory.
  [[nodiscard]] std::size_t stored_size() const noexcept {
    if (length_ == 0) return 0;
    return file_size(path_);
  }

  /// The file's path ("" if the path given was too long).
  [[nodiscard]] const char* path() const noexcept { return path_; }

  /// How many temporary files of saves killed before they ended (`<path>.<pid>.<n>.tmp` of a
  /// process no longer running) this object removed when it was made.
  [[nodiscard]] std::size_t removed_temporaries() const noexcept { return removed_temporaries_; }

 private:
  static constexpr char previous_suffix[] = ".previous";
  static constexpr char rejected_suffix[] = ".rejected";
  /// Room for the path and its longest suffix, `.<pid>.<n>.tmp` (two 20-digit numbers).
  static constexpr std::size_t name_capacity = max_path + 48;

  /// `out` = the path from `from` (0: all of it, name_: the file's name) followed by `suffix`.
  char* with_suffix(char (&out)[name_capacity], std::size_t from, const char* suffix) const noexcept {
    std::size_t n = 0;
    for (std::size_t i = from; i < length_; ++i) out[n++] = path_[i];
    for (std::size_t i = 0; suffix[i] != '\0'; ++i) out[n++] = suffix[i];
    out[n] = '\0';
    return out;
  }

#if (defined(__unix__) || defined(__APPLE__)) && __has_include(<unistd.h>)
  /// Attempts at a unique name before a save gives up (each name found taken costs one).
  static constexpr int name_attempts = 64;
  /// The largest single read or write (a size_t count beyond SSIZE_MAX is undefined).
  static constexpr std::size_t max_transfer = std::size_t{1} << 30;

  /// A file descriptor, closed when it goes out of scope (or by close()).
  class descriptor {
   public:
    explicit descriptor(int fd) noexcept : fd_(fd) {}
    ~descriptor() {
      if (fd_ >= 0) ::close(fd_);
    }
    descriptor(const descriptor&) = delete;
    descriptor& operator=(const descriptor&) = delete;
    [[nodiscard]] int get() const noexcept { return fd_; }
    /// Closes now; FALSE if close reported an error (EINTR is none: the descriptor is closed
    /// then, and closing it again could close another thread's).
    bool close() noexcept {
      const int fd = fd_;
      fd_ = -1;
      return ::close(fd) == 0 || errno == EINTR;
    }

   private:
    int fd_;
  };

  /// The file's name within its directory.
  [[nodiscard]] const char* name() const noexcept { return path_ + name_; }

  /// `out` = the file's name followed by `.<pid>.<n>.tmp`, a name no other save uses.
  char* unique_name(char (&out)[name_capacity]) const noexcept {
    char* end = with_suffix(out, name_, ".");
    while (*end != '\0') ++end;
    end = append_number(end, static_cast<unsigned long long>(::getpid()));
    *end++ = '.';
    end = append_number(end, detail::file_storage_names_taken.fetch_add(1, std::memory_order_relaxed));
    const char tmp[] = ".tmp";
    for (const char c : tmp) *end++ = c;
    return out;
  }

  static char* append_number(char* out, unsigned long long value) noexcept {
    char digits[20];
    int n = 0;
    do {
      digits[n++] = static_cast<char>('0' + value % 10);
      value /= 10;
    } while (value != 0);
    while (n > 0) *out++ = digits[--n];
    return out;
  }

  /// The directory that holds the file, opened to sync it and to name files relative to it
  /// (so that every name of one save is in the same directory).
  [[nodiscard]] int open_directory() const noexcept {
    char directory[max_path + 1];
    if (name_ == 0) {
      directory[0] = '.';
      directory[1] = '\0';
    } else {
      const std::size_t n = name_ == 1 ? 1 : name_ - 1;  // "/name": the root; "a/name": "a"
      for (std::size_t i = 0; i < n; ++i) directory[i] = path_[i];
      directory[n] = '\0';
    }
    int fd = -1;
    do fd = ::open(directory, O_RDONLY | O_DIRECTORY | O_CLOEXEC);
    while (fd < 0 && errno == EINTR);
    return fd;
  }

  static bool write_all(int fd, std::span<const std::byte> data) noexcept {
    const std::byte* next = data.data();
    std::size_t left = data.size();
    while (left > 0) {
      const ::ssize_t written = ::write(fd, next, left < max_transfer ? left : max_transfer);
      if (written < 0 && errno == EINTR) continue;
      if (written <= 0) return false;
      next += written;
      left -= static_cast<std::size_t>(written);
    }
    return true;
  }

  /// Brings the file's data (or the directory's entries) to the disk.
  static bool sync(int fd) noexcept {
#if defined(__APPLE__)
    if (::fcntl(fd, F_FULLFSYNC) == 0) return true;  // macOS's fsync leaves it in the drive's cache
#endif
    int result = 0;
    do result = ::fsync(fd);
    while (result != 0 && errno == EINTR);
    return result == 0;
  }

  /// Syncs the directory; a file system that cannot sync a directory (EINVAL) is no error.
  static bool sync_directory(int fd) noexcept { return sync(fd) || errno == EINVAL; }

  /// The pid in `entry` if it is a temporary name of this file's saves, `<name>.<pid>.<n>.tmp`
  /// (pid and n decimal); 0 otherwise.
  [[nodiscard]] ::pid_t temporary_of(const char* entry) const noexcept {
    const char* own = name();
    std::size_t i = 0;
    for (; own[i] != '\0'; ++i) {
      if (entry[i] != own[i]) return 0;
    }
    if (entry[i++] != '.') return 0;
    unsigned long long pid = 0;
    std::size_t digits = 0;
    for (; entry[i] >= '0' && entry[i] <= '9' && digits < 19; ++i, ++digits) {
      pid = pid * 10 + static_cast<unsigned long long>(entry[i] - '0');
    }
    if (digits == 0 || entry[i++] != '.') return 0;
    digits = 0;
    for (; entry[i] >= '0' && entry[i] <= '9'; ++i) ++digits;
    if (digits == 0 || entry[i] != '.' || entry[i + 1] != 't' || entry[i + 2] != 'm' || entry[i + 3] != 'p' ||
        entry[i + 4] != '\0') {
      return 0;
    }
    const auto as_pid = static_cast<::pid_t>(pid);
    return as_pid > 0 && static_cast<unsigned long long>(as_pid) == pid ? as_pid : 0;
  }

  /// Removes the temporary files of this file's saves whose process no longer runs (kill(pid,
  /// 0) says ESRCH); this process's own are left alone. Reads the directory with getdents64
  /// into a buffer on the stack (opendir allocates). The number removed.
  std::size_t remove_stale_temporaries() noexcept {
#if defined(__linux__) && __has_include(<dirent.h>) && defined(__GLIBC__) && \
    (__GLIBC__ > 2 || (__GLIBC__ == 2 && __GLIBC_MINOR__ >= 30))
    const descriptor directory(open_directory());
    if (directory.get() < 0) return 0;
    const ::pid_t self = ::getpid();
    std::size_t removed = 0;
    alignas(struct dirent64) char buffer[4096];
    for (;;) {
      const ::ssize_t got = ::getdents64(directory.get(), buffer, sizeof buffer);
      if (got < 0 && errno == EINTR) continue;
      if (got <= 0) break;
      for (::ssize_t at = 0; at < got;) {
        struct dirent64 entry {};
        // The records are packed; copy the fixed part out rather than cast an unaligned address.
        std::memcpy(&entry, buffer + at, offsetof(struct dirent64, d_name));
        const char* entry_name = buffer + at + offsetof(struct dirent64, d_name);
        const ::pid_t pid = temporary_of(entry_name);
        if (pid != 0 && pid != self && ::kill(pid, 0) != 0 && errno == ESRCH &&
            ::unlinkat(directory.get(), entry_name, 0) == 0) {
          ++removed;
        }
        if (entry.d_reclen == 0) break;
        at += entry.d_reclen;
      }
    }
    return removed;
#else
    return 0;  // no way to list a directory without allocating here: the files stay
#endif
  }

  /// Creates and opens a new temporary file, its name in `out`; -1 on failure.
  int create_temporary(int directory, char (&out)[name_capacity]) noexcept {
    for (int attempt = 0; attempt < name_attempts; ++attempt) {
      int fd = -1;
      do
        fd = ::openat(directory, unique_name(out), O_WRONLY | O_CREAT | O_EXCL | O_NOFOLLOW | O_CLOEXEC | O_NOCTTY,
                      S_IRUSR | S_IWUSR | S_IRGRP | S_IWGRP | S_IROTH | S_IWOTH);  // less the umask
      while (fd < 0 && errno == EINTR);
      if (fd >= 0 || errno != EEXIST) return fd;
    }
    return -1;
  }

  /// Makes the current file, if any, `<path>.previous`, leaving it at `<path>` too where the
  /// file system has hard links.
  bool keep_previous(int directory) noexcept {
    char previous[name_capacity];
    with_suffix(previous, name_, previous_suffix);
    // An empty current file holds no image: the previous one stays (the last image there is).
    struct stat current {};
    if (::fstatat(directory, name(), &current, AT_SYMLINK_NOFOLLOW) == 0 && S_ISREG(current.st_mode) &&
        current.st_size == 0) {
      return true;
    }
    char second_name[name_capacity];
    for (int attempt = 0; attempt < name_attempts; ++attempt) {
      // linkat without AT_SYMLINK_FOLLOW links a symbolic link itself, not its target.
      if (::linkat(directory, name(), directory, unique_name(second_name), 0) == 0) {
        const bool renamed = ::renameat(directory, second_name, directory, previous) == 0;
        // Gone if renamed, unless `<path>.previous` already was this file (another save just
        // made it so), where rename does nothing.
        ::unlinkat(directory, second_name, 0);
        return renamed;
      }
      if (errno == ENOENT) return true;  // no current file: the previous one stays
      if (errno == EEXIST || errno == EINTR) continue;
      // No hard links here (or none to this file, EPERM): move the file itself, unless it is
      // a directory, which is no image.
      struct stat status {};
      if (::fstatat(directory, name(), &status, AT_SYMLINK_NOFOLLOW) != 0) return errno == ENOENT;
      if (S_ISDIR(status.st_mode)) return false;
      return ::renameat(directory, name(), directory, previous) == 0 || errno == ENOENT;
    }
    return false;
  }

  bool save_file(std::span<const std::byte> data) noexcept {
    const descriptor directory(open_directory());
    if (directory.get() < 0) return false;
    char temporary[name_capacity];
    descriptor file(create_temporary(directory.get(), temporary));
    if (file.get() < 0) return false;
    bool done = write_all(file.get(), data) && sync(file.get());
    done = file.close() && done;
    done =
        done && keep_previous(directory.get()) && ::renameat(directory.get(), temporary, directory.get(), name()) == 0;
    if (!done) {
      ::unlinkat(directory.get(), temporary, 0);
      return false;
    }
    return sync_directory(directory.get());
  }

  static std::size_t load_file(const char* file_name, std::span<std::byte> buffer) noexcept {
    int fd = -1;
    // O_NONBLOCK: a FIFO planted at the name does not block the open (it is no regular file).
    do fd = ::open(file_name, O_RDONLY | O_CLOEXEC | O_NOCTTY | O_NONBLOCK);
    while (fd < 0 && errno == EINTR);
    const descriptor file(fd);
    if (fd < 0) return 0;
    struct stat status {};
    if (::fstat(fd, &status) != 0 || !S_ISREG(status.st_mode)) return 0;
    if (status.st_size < 0 || static_cast<unsigned long long>(status.st_size) > buffer.size()) return 0;
    std::size_t total = 0;
    while (total < buffer.size()) {
      const std::size_t wanted = buffer.size() - total;
      const ::ssize_t got = ::read(fd, buffer.data() + total, wanted < max_transfer ? wanted : max_transfer);
      if (got < 0 && errno == EINTR) continue;
      if (got < 0) return 0;
      if (got == 0) return total;
      total += static_cast<std::size_t>(got);
    }
    // The buffer is full: the file must end here.
    for (;;) {
      std::byte beyond{};
      const ::ssize_t got = ::read(fd, &beyond, 1);
      if (got < 0 && errno == EINTR) continue;
      return got == 0 ? total : 0;
    }
  }

  static std::size_t file_size(const char* file_name) noexcept {
    struct stat status {};
    if (::stat(file_name, &status) != 0 || !S_ISREG(status.st_mode) || status.st_size < 0) return 0;
    return static_cast<std::size_t>(status.st_size);
  }

  bool set_aside_file() noexcept {
    const descriptor directory(open_directory());
    if (directory.get() < 0) return errno == ENOENT;  // no directory, no file
    char rejected[name_capacity];
    if (::renameat(directory.get(), name(), directory.get(), with_suffix(rejected, name_, rejected_suffix)) != 0) {
      return errno == ENOENT;
    }
    return sync_directory(directory.get());
  }
#else
  /// Nothing to remove here: the fixed `<path>.tmp` may be another process's save under way.
  static std::size_t remove_stale_temporaries() noexcept { return 0; }

  bool save_file(std::span<const std::byte> data) noexcept {
    char temporary[name_capacity];
    with_suffix(temporary, 0, ".tmp");
    std::FILE* file = std::fopen(temporary, "wb");
    if (file == nullptr) return false;
    const bool written = data.empty() || std::fwrite(data.data(), 1, data.size(), file) == data.size();
    const bool flushed = std::fflush(file) == 0;
    const bool closed = std::fclose(file) == 0;
    if (!written || !flushed || !closed) {
      std::remove(temporary);
      return false;
    }
    // The current file becomes the previous one (rename does not replace a file everywhere:
    // not on Windows); then <path> is free for the new one.
    char previous[name_capacity];
    with_suffix(previous, 0, previous_suffix);
    if (exists(path_)) {
      std::remove(previous);
      std::rename(path_, previous);
    }
    if (std::rename(temporary, path_) == 0) return true;
    std::remove(temporary);
    return false;
  }

  static bool exists(const char* file_name) noexcept {
    std::FILE* file = std::fopen(file_name, "rb");
    if (file == nullptr) return false;
    std::fclose(file);
    return true;
  }

  static std::size_t load_file(const char* file_name, std::span<std::byte> buffer) noexcept {
    std::FILE* file = std::fopen(file_name, "rb");
    if (file == nullptr) return 0;
    const std::size_t read = buffer.empty() ? 0 : std::fread(buffer.data(), 1, buffer.size(), file);
    const bool failed = std::ferror(file) != 0;
    const bool more = !failed && std::fgetc(file) != EOF;  // the file is larger than the buffer
    std::fclose(file);
    return failed || more ? 0 : read;
  }

  static std::size_t file_size(const char* file_name) noexcept {
    std::FILE* file = std::fopen(file_name, "rb");
    if (file == nullptr) return 0;
    const bool sought = std::fseek(file, 0, SEEK_END) == 0;
    const long size = sought ? std::ftell(file) : -1;
    std::fclose(file);
    return size < 0 ? 0 : static_cast<std::size_t>(size);
  }

  bool set_aside_file() noexcept {
    if (!exists(path_)) return true;
    char rejected[name_capacity];
    with_suffix(rejected, 0, rejected_suffix);
    std::remove(rejected);
    return std::rename(path_, rejected) == 0;
  }
#endif

  char path_[max_path + 1]{};
  std::size_t length_ = 0;
  std::size_t removed_temporaries_ = 0;
  std::size_t name_ = 0;  // where the file's name starts in path_ (after the last '/')
};

}  // namespace iecoop

#include <iecoop/detail/pop_macros.hpp>
