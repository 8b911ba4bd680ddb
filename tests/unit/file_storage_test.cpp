// file_storage: the RETAIN/PERSISTENT image in a file, written atomically.
#include "iecoop_test.hpp"

#include <iecoop/runtime/file_storage.hpp>
#include <iecoop/runtime/retain.hpp>

#include <algorithm>
#include <array>
#include <cstddef>
#include <filesystem>
#include <fstream>
#include <random>
#include <span>
#include <string>

using namespace iecoop;

namespace {

static_assert(RetainStorage<file_storage>);

/// A file name of its own in the temporary directory (test cases may run in parallel
/// processes), removed with its `.tmp` at the end of the test case.
class temp_file {
 public:
  explicit temp_file(const char* stem) {
    std::random_device random;
    path_ = (std::filesystem::temp_directory_path() /
             (std::string("iecoop_") + stem + "_" + std::to_string(random()) + "_" + std::to_string(random()) + ".bin"))
                .string();
  }
  ~temp_file() {
    std::error_code ignored;
    std::filesystem::remove(path_, ignored);
    std::filesystem::remove(tmp(), ignored);
  }
  temp_file(const temp_file&) = delete;
  temp_file& operator=(const temp_file&) = delete;

  [[nodiscard]] const char* c_str() const { return path_.c_str(); }
  [[nodiscard]] std::string tmp() const { return path_ + ".tmp"; }
  [[nodiscard]] bool exists() const { return std::filesystem::exists(path_); }
  [[nodiscard]] std::uintmax_t size() const { return std::filesystem::file_size(path_); }

 private:
  std::string path_;
};

void write_file(const std::string& path, const std::string& text) {
  std::ofstream out(path, std::ios::binary);
  out << text;
}

template <std::size_t N>
std::array<std::byte, N> bytes(const char (&text)[N]) {
  std::array<std::byte, N> result{};
  for (std::size_t i = 0; i < N; ++i) result[i] = static_cast<std::byte>(text[i]);
  return result;
}

struct PRG_Plant : program<PRG_Plant> {
  INT iCycles;
  retain<DINT> diCount{1};
  persistent<STRING<10>> sSite{"none"};
  void body() {}
};

}  // namespace

TEST_SUITE("file_storage") {
  TEST_CASE("save then load gives the same bytes, and no .tmp is left") {
    const temp_file file("roundtrip");
    file_storage storage(file.c_str());
    CHECK(std::string(storage.path()) == file.c_str());
    const auto data = bytes("retained bytes");
    CHECK(storage.save(data));
    CHECK(file.exists());
    CHECK(file.size() == data.size());
    CHECK(!std::filesystem::exists(file.tmp()));

    std::array<std::byte, 64> buffer{};
    CHECK(storage.load(buffer) == data.size());
    CHECK(std::equal(data.begin(), data.end(), buffer.begin()));

    // A second save replaces the file, also with fewer bytes.
    const auto shorter = bytes("new");
    CHECK(storage.save(shorter));
    CHECK(storage.load(buffer) == shorter.size());
    CHECK(std::equal(shorter.begin(), shorter.end(), buffer.begin()));
    CHECK(!std::filesystem::exists(file.tmp()));
  }

  TEST_CASE("a missing file, an empty file and a file larger than the buffer load nothing") {
    const temp_file file("missing");
    file_storage storage(file.c_str());
    std::array<std::byte, 4> buffer{};
    CHECK(storage.load(buffer) == 0);
    CHECK(storage.save({}));
    CHECK(file.exists());
    CHECK(storage.load(buffer) == 0);
    CHECK(storage.save(bytes("four")));  // 5 bytes with the NUL
    CHECK(storage.load(buffer) == 0);
    std::array<std::byte, 5> exact{};
    CHECK(storage.load(exact) == 5);
  }

  TEST_CASE("a write interrupted before the rename leaves the previous file") {
    const temp_file file("atomic");
    file_storage storage(file.c_str());
    CHECK(storage.save(bytes("old image")));
    write_file(file.tmp(), "half a new ima");  // what a crash during save leaves behind
    std::array<std::byte, 64> buffer{};
    CHECK(storage.load(buffer) == sizeof("old image"));
    CHECK(static_cast<char>(buffer[0]) == 'o');
    CHECK(storage.save(bytes("new image")));  // the next save overwrites the leftover
    CHECK(!std::filesystem::exists(file.tmp()));
    CHECK(storage.load(buffer) == sizeof("new image"));
    CHECK(static_cast<char>(buffer[0]) == 'n');
  }

  TEST_CASE("a save into a directory that does not exist fails and leaves nothing") {
    const std::string path =
        (std::filesystem::temp_directory_path() / "iecoop_no_such_directory_4711" / "retain.bin").string();
    file_storage storage(path.c_str());
    CHECK(!storage.save(bytes("data")));
    CHECK(!std::filesystem::exists(path));
    CHECK(!std::filesystem::exists(path + ".tmp"));
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

    const std::string longest(file_storage::max_path, 'y');
    const file_storage fits(longest.c_str());
    CHECK(faults.count == 1);
    CHECK(std::string(fits.path()) == longest);
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
