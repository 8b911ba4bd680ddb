// file_storage: the RETAIN/PERSISTENT image in a file, replaced atomically through an
// exclusive temporary file, with the image before the last save in `<path>.previous` and a
// rejected one in `<path>.rejected`; links planted at its names are never written through;
// processes killed while saving and processes saving at once leave whole images.
#include "iecoop_test.hpp"

#include <iecoop/runtime/file_storage.hpp>
#include <iecoop/runtime/retain.hpp>

#include <algorithm>
#include <array>
#include <chrono>
#include <csignal>
#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <optional>
#include <random>
#include <span>
#include <string>
#include <thread>
#include <vector>

#include <sys/resource.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

using namespace iecoop;

namespace {

static_assert(RetainStorage<file_storage>);
static_assert(RetainStorageWithPrevious<file_storage>);
static_assert(RetainStorageSetAside<file_storage>);

/// A directory of its own (test cases may run in parallel processes) for the storage's file
/// `retain.bin`, removed with everything in it at the end of the test case: the file, its
/// `.previous` and `.rejected`, temporary files of saves cut short, whatever a test planted.
class temp_file {
 public:
  explicit temp_file(const char* stem, const std::filesystem::path& parent = std::filesystem::temp_directory_path()) {
    std::random_device random;
    directory_ =
        parent / (std::string("iecoop_") + stem + "_" + std::to_string(random()) + "_" + std::to_string(random()));
    std::filesystem::create_directory(directory_);
    path_ = (directory_ / "retain.bin").string();
  }
  ~temp_file() {
    std::error_code ignored;
    std::filesystem::remove_all(directory_, ignored);
  }
  temp_file(const temp_file&) = delete;
  temp_file& operator=(const temp_file&) = delete;

  [[nodiscard]] const char* c_str() const { return path_.c_str(); }
  [[nodiscard]] const std::string& str() const { return path_; }
  [[nodiscard]] std::string previous() const { return path_ + ".previous"; }
  [[nodiscard]] std::string rejected() const { return path_ + ".rejected"; }
  /// The fixed temporary name the storage once used.
  [[nodiscard]] std::string tmp() const { return path_ + ".tmp"; }
  /// The n-th temporary name (from 0) the saves of this process take from now on:
  /// `<path>.<pid>.<k>.tmp`, k counting the names the process took before.
  [[nodiscard]] std::string temporary(unsigned long n) const {
    return path_ + "." + std::to_string(::getpid()) + "." +
           std::to_string(iecoop::detail::file_storage_names_taken.load() + n) + ".tmp";
  }
  [[nodiscard]] const std::filesystem::path& directory() const { return directory_; }
  [[nodiscard]] bool exists() const { return std::filesystem::exists(path_); }
  [[nodiscard]] std::uintmax_t size() const { return std::filesystem::file_size(path_); }

  /// The regular files in the directory whose names end in `.tmp`: what saves left behind.
  [[nodiscard]] std::vector<std::string> temporary_files() const {
    std::vector<std::string> found;
    for (const auto& entry : std::filesystem::directory_iterator(directory_)) {
      const std::string name = entry.path().filename().string();
      if (entry.is_regular_file() && !entry.is_symlink() && name.ends_with(".tmp")) found.push_back(name);
    }
    return found;
  }

 private:
  std::filesystem::path directory_;
  std::string path_;
};

/// Where saves are fast (tmpfs, whose fsync does nothing) for the tests that make thousands
/// of them; they check the order of the steps, not the disk.
std::filesystem::path fast_directory() {
  std::error_code ignored;
  if (std::filesystem::is_directory("/dev/shm", ignored) && ::access("/dev/shm", W_OK) == 0) return "/dev/shm";
  return std::filesystem::temp_directory_path();
}

void write_file(const std::string& path, const std::string& text) {
  std::ofstream out(path, std::ios::binary);
  out << text;
}

std::string read_file(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

template <std::size_t N>
std::array<std::byte, N> bytes(const char (&text)[N]) {
  std::array<std::byte, N> result{};
  for (std::size_t i = 0; i < N; ++i) result[i] = static_cast<std::byte>(text[i]);
  return result;
}

std::string text_of(std::span<const std::byte> data) {
  std::string text;
  for (const std::byte b : data) text.push_back(static_cast<char>(b));
  return text;
}

// --- Self-checking images, for the tests with processes ------------------------------------

constexpr std::size_t largest_image = 64 + 20000;

/// The image number `sequence` of `writer`: "IMG1", the writer, the number and the size (each
/// a little-endian u32), then bytes that follow from writer and number. Sizes vary from 64 to
/// about 20 000 bytes, over several pages.
std::vector<std::byte> make_image(std::uint32_t writer, std::uint32_t sequence) {
  const std::size_t size = 64 + (static_cast<std::size_t>(sequence) * 2654435761U >> 8) % 20000;
  std::vector<std::byte> image(size);
  const auto put = [&](std::size_t at, std::uint32_t value) {
    for (std::size_t i = 0; i < 4; ++i) image[at + i] = static_cast<std::byte>(value >> (8 * i));
  };
  image[0] = std::byte{'I'};
  image[1] = std::byte{'M'};
  image[2] = std::byte{'G'};
  image[3] = std::byte{'1'};
  put(4, writer);
  put(8, sequence);
  put(12, static_cast<std::uint32_t>(size));
  std::uint64_t state = (std::uint64_t{writer} << 32 | sequence) * 0x9E3779B97F4A7C15ULL + 1;
  for (std::size_t i = 16; i < size; ++i) {
    state ^= state << 13;
    state ^= state >> 7;
    state ^= state << 17;
    image[i] = static_cast<std::byte>(state);
  }
  return image;
}

struct image_id {
  std::uint32_t writer;
  std::uint32_t sequence;
};

/// Which image `data` is, if it is exactly one that make_image makes.
std::optional<image_id> identify(std::span<const std::byte> data) {
  if (data.size() < 16) return std::nullopt;
  const auto get = [&](std::size_t at) {
    std::uint32_t value = 0;
    for (std::size_t i = 0; i < 4; ++i) value |= std::to_integer<std::uint32_t>(data[at + i]) << (8 * i);
    return value;
  };
  const image_id id{get(4), get(8)};
  const std::vector<std::byte> expected = make_image(id.writer, id.sequence);
  if (!std::equal(data.begin(), data.end(), expected.begin(), expected.end())) return std::nullopt;
  return id;
}

/// In a child process: saves images `first`, `first + 1`, ... of `writer` to `path`, `count`
/// of them (0: until killed), writing a byte to `saved` (if not -1) after the first; exits with
/// 0 when done, 3 if a save failed.
[[noreturn]] void save_images(const char* path, std::uint32_t writer, std::uint32_t first, std::uint32_t count,
                              int saved = -1) {
  file_storage storage(path);
  for (std::uint32_t sequence = first; count == 0 || sequence < first + count; ++sequence) {
    if (!storage.save(make_image(writer, sequence))) ::_exit(3);
    if (sequence == first && saved >= 0 && ::write(saved, "s", 1) != 1) ::_exit(4);
  }
  ::_exit(0);
}

struct PRG_Plant : program<PRG_Plant> {
  INT iCycles;
  retain<DINT> diCount{1};
  persistent<STRING<10>> sSite{"none"};
  void body() {}
};

}  // namespace

TEST_SUITE("file_storage") {
  TEST_CASE("save then load gives the same bytes, and no temporary file is left") {
    const temp_file file("roundtrip");
    file_storage storage(file.c_str());
    CHECK(std::string(storage.path()) == file.c_str());
    const auto data = bytes("retained bytes");
    CHECK(storage.save(data));
    CHECK(file.exists());
    CHECK(file.size() == data.size());
    CHECK(file.temporary_files().empty());

    std::array<std::byte, 64> buffer{};
    CHECK(storage.load(buffer) == data.size());
    CHECK(std::equal(data.begin(), data.end(), buffer.begin()));

    // A second save replaces the file, also with fewer bytes.
    const auto shorter = bytes("new");
    CHECK(storage.save(shorter));
    CHECK(storage.load(buffer) == shorter.size());
    CHECK(std::equal(shorter.begin(), shorter.end(), buffer.begin()));
    CHECK(file.temporary_files().empty());
  }

  TEST_CASE("a missing file, an empty file and a file larger than the buffer load nothing") {
    const temp_file file("missing");
    file_storage storage(file.c_str());
    std::array<std::byte, 4> buffer{};
    CHECK(storage.load(buffer) == 0);
    CHECK(storage.load_previous(buffer) == 0);
    CHECK(storage.save({}));
    CHECK(file.exists());
    CHECK(storage.load(buffer) == 0);
    CHECK(storage.save(bytes("four")));  // 5 bytes with the NUL
    CHECK(storage.load(buffer) == 0);
    std::array<std::byte, 5> exact{};
    CHECK(storage.load(exact) == 5);
    CHECK(storage.load(std::span<std::byte>()) == 0);
  }

  TEST_CASE("what is no regular file loads nothing, without blocking on a FIFO") {
    const temp_file file("not_regular");
    const file_storage storage(file.c_str());
    std::array<std::byte, 16> buffer{};
    REQUIRE(::mkfifo(file.c_str(), 0600) == 0);
    CHECK(storage.load(buffer) == 0);
    std::filesystem::create_directory(file.previous());
    CHECK(storage.load_previous(buffer) == 0);
  }

  TEST_CASE("each save keeps the image it replaces as the previous one") {
    const temp_file file("previous");
    file_storage storage(file.c_str());
    std::array<std::byte, 64> buffer{};
    CHECK(storage.save(bytes("first")));
    CHECK(storage.load_previous(buffer) == 0);  // nothing before the first
    CHECK(!std::filesystem::exists(file.previous()));

    CHECK(storage.save(bytes("second image")));
    CHECK(text_of(std::span(buffer).first(storage.load(buffer))) == std::string("second image", 13));
    CHECK(text_of(std::span(buffer).first(storage.load_previous(buffer))) == std::string("first", 6));

    CHECK(storage.save(bytes("third")));
    CHECK(text_of(std::span(buffer).first(storage.load(buffer))) == std::string("third", 6));
    CHECK(text_of(std::span(buffer).first(storage.load_previous(buffer))) == std::string("second image", 13));
    std::array<std::byte, 8> small{};
    CHECK(storage.load_previous(small) == 0);  // larger than the buffer
    CHECK(file.temporary_files().empty());

    // Another object on the same path (the next run) sees the same two images.
    const file_storage next_run(file.c_str());
    CHECK(next_run.load_previous(buffer) == 13);
  }

  TEST_CASE("set_aside moves the image out of the way of later saves, the previous one stays") {
    const temp_file file("set_aside");
    file_storage storage(file.c_str());
    std::array<std::byte, 64> buffer{};
    const auto load = [&] { return text_of(std::span(buffer).first(storage.load(buffer))); };
    const auto load_previous = [&] { return text_of(std::span(buffer).first(storage.load_previous(buffer))); };

    CHECK(storage.set_aside());  // nothing to set aside
    CHECK(!std::filesystem::exists(file.rejected()));
    CHECK(storage.save(bytes("good")));
    CHECK(storage.save(bytes("damaged")));
    CHECK(storage.set_aside());
    CHECK(!file.exists());
    CHECK(load().empty());
    CHECK(load_previous() == std::string("good", 5));
    CHECK(read_file(file.rejected()) == std::string("damaged", 8));

    // The next save finds no current image: the previous one stays, the rejected one too.
    CHECK(storage.save(bytes("fresh")));
    CHECK(load() == std::string("fresh", 6));
    CHECK(load_previous() == std::string("good", 5));
    CHECK(read_file(file.rejected()) == std::string("damaged", 8));
    CHECK(storage.save(bytes("later")));
    CHECK(load_previous() == std::string("fresh", 6));
    CHECK(read_file(file.rejected()) == std::string("damaged", 8));

    // A second set_aside replaces the rejected image.
    CHECK(storage.set_aside());
    CHECK(read_file(file.rejected()) == std::string("later", 6));
    CHECK(load().empty());
    CHECK(file.temporary_files().empty());
  }

  TEST_CASE("a leftover temporary file is never used; the next start removes those of processes that ended") {
    const temp_file file("atomic");
    file_storage storage(file.c_str());
    CHECK(storage.save(bytes("old image")));
    CHECK(storage.removed_temporaries() == 0);
    // What a save killed while writing leaves: the temporary file of a process that has ended ...
    const pid_t ended = ::fork();
    REQUIRE(ended >= 0);
    if (ended == 0) ::_exit(0);
    int status = -1;
    REQUIRE(::waitpid(ended, &status, 0) == ended);
    const std::string dead = file.str() + "." + std::to_string(ended) + ".7.tmp";
    write_file(dead, "half a new ima");
    // ... one of a process still running (the test's parent), which may be saving ...
    const std::string running = file.str() + "." + std::to_string(::getppid()) + ".3.tmp";
    write_file(running, "half a new ima");
    // ... one of this process, at the name its next save tries first (it skips it) ...
    const std::string own = file.temporary(0);
    write_file(own, "half a new ima");
    // ... the fixed name of the <cstdio> fallback, and names that only look like a save's.
    write_file(file.tmp(), "half a new ima");
    const std::vector<std::string> lookalikes = {
        file.str() + "." + std::to_string(ended) + ".tmp",                                // no n
        file.str() + ".x" + std::to_string(ended) + ".1.tmp",                             // no pid
        file.str() + "." + std::to_string(ended) + ".1.tmp.saved",                        // another suffix
        (file.directory() / ("other.bin." + std::to_string(ended) + ".1.tmp")).string(),  // another file's
    };
    for (const std::string& name : lookalikes) write_file(name, "not ours");

    file_storage next_run(file.c_str());
    CHECK(next_run.removed_temporaries() == 1);
    CHECK_FALSE(std::filesystem::exists(dead));
    CHECK(read_file(running) == "half a new ima");
    CHECK(read_file(own) == "half a new ima");
    CHECK(read_file(file.tmp()) == "half a new ima");
    for (const std::string& name : lookalikes) CHECK(read_file(name) == "not ours");
    std::array<std::byte, 64> buffer{};
    CHECK(next_run.load(buffer) == sizeof("old image"));
    CHECK(static_cast<char>(buffer[0]) == 'o');
    CHECK(next_run.save(bytes("new image")));
    CHECK(next_run.load(buffer) == sizeof("new image"));
    CHECK(static_cast<char>(buffer[0]) == 'n');
    CHECK(read_file(own) == "half a new ima");
  }

  TEST_CASE("an empty <path> holds no image: the save after it keeps <path>.previous") {
    const temp_file file("empty_current");
    file_storage storage(file.c_str());
    CHECK(storage.save(bytes("first")));
    CHECK(storage.save(bytes("second")));
    write_file(file.str(), "");  // its data lost, or truncated by a tool
    std::array<std::byte, 64> buffer{};
    CHECK(storage.load(buffer) == 0);
    REQUIRE(storage.load_previous(buffer) == sizeof("first"));
    CHECK(storage.save(bytes("third")));
    CHECK(storage.load(buffer) == sizeof("third"));
    CHECK(static_cast<char>(buffer[0]) == 't');
    // The last image there was is still reachable: the empty file did not take its place.
    REQUIRE(storage.load_previous(buffer) == sizeof("first"));
    CHECK(static_cast<char>(buffer[0]) == 'f');
    // From then on, as ever: the save after it makes "third" the previous image.
    CHECK(storage.save(bytes("fourth")));
    REQUIRE(storage.load_previous(buffer) == sizeof("third"));
    CHECK(file.temporary_files().empty());
  }

  TEST_CASE("a save into a directory that does not exist fails and leaves nothing") {
    const temp_file file("no_directory");
    const std::string path = (file.directory() / "no_such_directory" / "retain.bin").string();
    file_storage storage(path.c_str());
    CHECK(!storage.save(bytes("data")));
    CHECK(!std::filesystem::exists(file.directory() / "no_such_directory"));
    CHECK(std::filesystem::is_empty(file.directory()));
    std::array<std::byte, 8> buffer{};
    CHECK(storage.load(buffer) == 0);
    CHECK(storage.load_previous(buffer) == 0);
    CHECK(storage.set_aside());  // there is no image
  }

  TEST_CASE("a failed save removes its temporary file and leaves the image it had") {
    const temp_file file("failed");
    file_storage storage(file.c_str());
    REQUIRE(storage.save(bytes("kept image")));
    std::array<std::byte, 64> buffer{};

    SUBCASE("the write fails: the file would exceed the process's file size limit") {
      const pid_t child = ::fork();
      REQUIRE(child >= 0);
      if (child == 0) {
        const rlimit limit{16, 16};
        ::signal(SIGXFSZ, SIG_IGN);  // write then fails with EFBIG instead of killing the process
        const bool saved = ::setrlimit(RLIMIT_FSIZE, &limit) == 0 &&
                           file_storage(file.c_str()).save(bytes("an image longer than sixteen bytes"));
        ::_exit(saved ? 1 : 0);
      }
      int status = -1;
      REQUIRE(::waitpid(child, &status, 0) == child);
      CHECK(WIFEXITED(status));
      CHECK(WEXITSTATUS(status) == 0);  // the save failed
    }
    SUBCASE("the rename fails: <path> is a directory") {
      const temp_file other("failed_rename");
      const std::string path = (other.directory() / "image").string();
      std::filesystem::create_directory(path);
      write_file(path + "/inside", "x");
      file_storage blocked(path.c_str());
      CHECK(!blocked.save(bytes("data")));
      CHECK(std::filesystem::is_directory(path));
      CHECK(!std::filesystem::exists(path + ".previous"));
      CHECK(other.temporary_files().empty());
    }
    CHECK(storage.load(buffer) == sizeof("kept image"));
    CHECK(static_cast<char>(buffer[0]) == 'k');
    CHECK(file.temporary_files().empty());
  }

  TEST_CASE("a symbolic link planted at a name a save uses is skipped or replaced, never written through") {
    const temp_file file("links");
    const std::string victim = (file.directory() / "victim").string();
    write_file(victim, "not an image");
    const auto plant = [&](const std::string& name) { std::filesystem::create_symlink(victim, name); };
    const auto is_link_to_victim = [&](const std::string& name) {
      return std::filesystem::is_symlink(name) && std::filesystem::read_symlink(name) == victim;
    };
    // The temporary names the next saves take first, the fixed one of earlier versions, and
    // the names of the two other images.
    std::vector<std::string> temporary_names{file.tmp()};
    for (unsigned long n = 0; n < 8; ++n) temporary_names.push_back(file.temporary(n));
    for (const std::string& name : temporary_names) plant(name);
    plant(file.previous());
    plant(file.rejected());

    file_storage storage(file.c_str());
    CHECK(storage.save(bytes("first image")));
    CHECK(storage.save(bytes("second image")));
    CHECK(storage.set_aside());
    CHECK(storage.save(bytes("third image")));
    CHECK(read_file(victim) == "not an image");
    for (const std::string& name : temporary_names) CHECK(is_link_to_victim(name));
    CHECK(read_file(file.str()) == std::string("third image", 12));
    CHECK(read_file(file.previous()) == std::string("first image", 12));
    CHECK(read_file(file.rejected()) == std::string("second image", 13));
    CHECK(!std::filesystem::is_symlink(file.previous()));
    CHECK(!std::filesystem::is_symlink(file.rejected()));
    CHECK(file.temporary_files().empty());

    SUBCASE("a link at <path> itself is replaced by the new file") {
      std::filesystem::remove(file.str());
      plant(file.str());
      CHECK(storage.save(bytes("fourth image")));
      CHECK(!std::filesystem::is_symlink(file.str()));
      CHECK(read_file(file.str()) == std::string("fourth image", 13));
      CHECK(read_file(victim) == "not an image");
    }
    SUBCASE("links at every name of many saves: a save gives up or goes past them") {
      std::vector<std::string> names;
      for (unsigned long n = 0; n < 300; ++n) names.push_back(file.temporary(n));
      for (const std::string& name : names) plant(name);
      const bool saved = storage.save(bytes("fifth image"));
      CHECK(read_file(victim) == "not an image");
      CHECK(read_file(file.str()) == (saved ? std::string("fifth image", 12) : std::string("third image", 12)));
      for (const std::string& name : names) CHECK(is_link_to_victim(name));
      CHECK(file.temporary_files().empty());
    }
  }

  TEST_CASE("a process killed at any moment of its saves leaves the old image or a new one, whole") {
    // A child saves images n, n + 1, ... (each of another size, each self-checking) as fast
    // as it can; once its first save is done, the parent kills it after a random time (0 to
    // 2 ms: up to some dozens of saves), then loads. A few hundred times: the image must be
    // whole, one the child wrote, never older than the one found before.
    const temp_file file("killed", fast_directory());
    const std::uint64_t seed = std::random_device()();
    CAPTURE(seed);
    std::mt19937_64 random(seed);
    file_storage storage(file.c_str());
    REQUIRE(storage.save(make_image(0, 0)));
    std::vector<std::byte> buffer(largest_image);
    std::uint32_t last = 0;
    int rounds = 0;
    int changes = 0;
    const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(3);
    for (; rounds < 300 && std::chrono::steady_clock::now() < deadline; ++rounds) {
      CAPTURE(rounds);
      const auto first = static_cast<std::uint32_t>(rounds + 1) * 1'000'000U;  // the child's own numbers
      int saved[2];
      REQUIRE(::pipe(saved) == 0);
      const pid_t child = ::fork();
      REQUIRE(child >= 0);
      if (child == 0) {
        ::close(saved[0]);
        save_images(file.c_str(), 1, first, 0, saved[1]);
      }
      ::close(saved[1]);
      char byte = 0;
      const bool started = ::read(saved[0], &byte, 1) == 1;
      ::close(saved[0]);
      if (started) std::this_thread::sleep_for(std::chrono::microseconds(random() % 2000));
      ::kill(child, SIGKILL);
      int status = -1;
      REQUIRE(::waitpid(child, &status, 0) == child);
      REQUIRE(WIFSIGNALED(status));  // killed, not ended by a failed save

      std::size_t size = storage.load(buffer);
      if (size == 0) size = storage.load_previous(buffer);  // killed between two renames (no hard links)
      const std::optional<image_id> found = identify(std::span(buffer).first(size));
      REQUIRE(found.has_value());
      CAPTURE(found->sequence);
      REQUIRE((found->sequence == last || (found->writer == 1 && found->sequence >= first)));
      if (found->sequence != last) ++changes;
      last = found->sequence;
      const std::size_t previous_size = storage.load_previous(buffer);
      if (previous_size > 0) REQUIRE(identify(std::span(buffer).first(previous_size)).has_value());
    }
    CHECK(rounds >= 20);
    CHECK(changes == rounds);  // each child saved (at least once)
    CHECK(storage.save(make_image(0, 1)));
    // The killed saves left temporary files (those killed while writing); the next start, a
    // new file_storage for the path, removes them all: their processes have ended.
    const std::size_t left = file.temporary_files().size();
    CAPTURE(left);
    const file_storage next_start(file.c_str());
    CHECK(next_start.removed_temporaries() == left);
    CHECK(file.temporary_files().empty());
  }

  TEST_CASE("two processes saving to one path at once: each image whole, the last save wins") {
    const temp_file file("concurrent", fast_directory());
    constexpr std::uint32_t saves = 1500;
    int start[2];
    REQUIRE(::pipe(start) == 0);
    std::array<pid_t, 2> children{};
    for (std::uint32_t writer = 1; writer <= 2; ++writer) {
      const pid_t child = ::fork();
      REQUIRE(child >= 0);
      if (child == 0) {
        ::close(start[1]);
        char go = 0;
        if (::read(start[0], &go, 1) != 0) ::_exit(4);  // waits for the parent to close its end
        save_images(file.c_str(), writer, 0, saves);
      }
      children[writer - 1] = child;
    }
    ::close(start[0]);
    ::close(start[1]);  // both start now

    // Meanwhile the parent reads, as a controller starting at that moment would.
    const file_storage storage(file.c_str());
    std::vector<std::byte> buffer(largest_image);
    int reads = 0;
    int torn = 0;
    std::array<int, 2> status{-1, -1};
    std::array<bool, 2> running{true, true};
    while (running[0] || running[1]) {
      for (std::size_t i = 0; i < 2; ++i) {
        if (running[i] && ::waitpid(children[i], &status[i], WNOHANG) == children[i]) running[i] = false;
      }
      std::size_t size = storage.load(buffer);
      if (size == 0) size = storage.load_previous(buffer);
      if (size == 0) continue;  // nothing saved yet
      ++reads;
      if (!identify(std::span(buffer).first(size))) ++torn;
    }
    CAPTURE(reads);
    CHECK(torn == 0);
    for (const int s : status) {
      CHECK(WIFEXITED(s));
      CHECK(WEXITSTATUS(s) == 0);  // every save succeeded
    }
    const std::optional<image_id> last = identify(std::span(buffer).first(storage.load(buffer)));
    REQUIRE(last.has_value());
    CHECK(last->sequence == saves - 1);  // the last save of the one that finished last
    CHECK(identify(std::span(buffer).first(storage.load_previous(buffer))).has_value());
    CHECK(file.temporary_files().empty());
  }

  TEST_CASE("a path longer than max_path is a fault, the storage then saves and loads nothing") {
    iecoop_test::fault_recorder faults;
    const std::string long_path(file_storage::max_path + 1, 'x');
    file_storage storage(long_path.c_str());
    CHECK(faults.count == 1);
    CHECK(faults.last_kind == fault_kind::invalid_value);
    CHECK(std::string(storage.path()).empty());
    CHECK(!storage.save(bytes("data")));
    std::array<std::byte, 8> buffer{};
    CHECK(storage.load(buffer) == 0);
    CHECK(storage.load_previous(buffer) == 0);
    CHECK(!storage.set_aside());

    const std::string longest(file_storage::max_path, 'y');
    const file_storage fits(longest.c_str());
    CHECK(faults.count == 1);
    CHECK(std::string(fits.path()) == longest);
  }

  TEST_CASE("a relative path saves in the working directory") {
    const temp_file file("relative");
    const std::filesystem::path before = std::filesystem::current_path();
    std::filesystem::current_path(file.directory());
    file_storage storage("retain.bin");
    const bool saved = storage.save(bytes("here")) && storage.save(bytes("again"));
    std::filesystem::current_path(before);
    CHECK(saved);
    CHECK(read_file(file.str()) == std::string("again", 6));
    CHECK(read_file(file.previous()) == std::string("here", 5));
    CHECK(file.temporary_files().empty());
  }

  TEST_CASE("a restart: the image of one run restores the variables of the next") {
    const temp_file file("restart");
    std::array<std::byte, 256> image{};
    {
      PRG_Plant plant;  // the first run
      plant.iCycles = 9;
      plant.diCount = 41;
      plant.sSite = "hall 2";
      const iecoop::detail::retained_object objects[] = {{&plant, sizeof plant}};
      const std::size_t size = iecoop::detail::save_retained(objects, kept_over(retain_event::restart), image);
      REQUIRE(size > 0);
      file_storage storage(file.c_str());
      CHECK(storage.save(std::span(image).first(size)));
    }
    image.fill(std::byte{0});
    PRG_Plant plant;  // the next run
    file_storage storage(file.c_str());
    const std::size_t size = storage.load(image);
    REQUIRE(size > 0);
    const iecoop::detail::retained_object objects[] = {{&plant, sizeof plant}};
    CHECK(iecoop::detail::restore_retained(objects, kept_over(retain_event::restart), std::span(image).first(size)) ==
          retain_kinds::both);
    CHECK(plant.iCycles == 0);
    CHECK(plant.diCount == 41);
    CHECK(plant.sSite == "hall 2");
  }
}
