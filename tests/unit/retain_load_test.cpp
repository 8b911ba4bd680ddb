// Loading RETAIN and PERSISTENT data that is not what was saved: values that are no values of
// their types (a BOOL of 2, a STRING without its end), a retyped STRUCT member, a damaged
// image (a flipped byte, truncated, another version), an image larger than the retain memory;
// what start() reports (retain_status, retain_info), the bInitRetains FB_Init gets, the
// storage's previous image, the rejected image set aside, and the retain memory checked at
// start. Issue 18, items 2 and 3.
#include "iecoop_test.hpp"

#include <iecoop/runtime/application.hpp>
#include <iecoop/runtime/file_storage.hpp>

#include <algorithm>
#include <array>
#include <cstddef>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <random>
#include <span>
#include <string>
#include <vector>

using namespace iecoop;
using iecoop_test::fault_recorder;

namespace {

// --- Values checked byte by byte -------------------------------------------------------

struct ST_Flags {
  BOOL bOn;
  USINT nCount;
  STRING<4> sName;
};

enum class E_Mode : INT::rep { Off, Manual, Auto = 5 };
enum class E_Loose : INT::rep { A, B };

}  // namespace

template <>
inline constexpr bool iecoop::enum_strict<E_Mode> = true;
template <>
inline constexpr auto iecoop::enum_components<E_Mode> = iecoop::components<E_Mode::Off, E_Mode::Manual, E_Mode::Auto>{};

namespace {

template <class T>
bool valid(std::initializer_list<unsigned> bytes) {
  std::array<std::byte, sizeof(T)> raw{};
  std::size_t i = 0;
  for (const unsigned b : bytes) raw.at(i++) = static_cast<std::byte>(b);
  return detail::valid_value_bytes<T>(raw.data());
}

template <class T>
std::array<std::byte, sizeof(T)> bytes_of(const T& value) {
  std::array<std::byte, sizeof(T)> raw{};
  std::memcpy(raw.data(), &value, sizeof(T));
  return raw;
}

}  // namespace

TEST_SUITE("retain: which bytes are values") {
  TEST_CASE("BOOL is 0 or 1") {
    CHECK(valid<BOOL>({0}));
    CHECK(valid<BOOL>({1}));
    CHECK_FALSE(valid<BOOL>({2}));
    CHECK_FALSE(valid<BOOL>({0xFF}));
    CHECK_FALSE(valid<bool>({2}));
  }

  TEST_CASE("STRING(n) ends within its n + 1 characters") {
    CHECK(valid<STRING<3>>({'a', 'b', 'c', 0}));
    CHECK(valid<STRING<3>>({0, 'x', 'y', 'z'}));  // '' (what follows the end is never read)
    CHECK_FALSE(valid<STRING<3>>({'a', 'b', 'c', 'd'}));
    auto wide = bytes_of(WSTRING<2>(u"ab"));
    CHECK(detail::valid_value_bytes<WSTRING<2>>(wide.data()));
    wide[4] = std::byte{'c'};  // the terminating char16_t, low byte
    CHECK_FALSE(detail::valid_value_bytes<WSTRING<2>>(wide.data()));
  }

  TEST_CASE("a subrange's value lies within its limits") {
    using percent = subrange<INT, 0, 100>;
    CHECK(valid<percent>({100, 0}));
    CHECK(valid<percent>({0, 0}));
    CHECK_FALSE(valid<percent>({101, 0}));
    CHECK_FALSE(valid<percent>({0xFF, 0xFF}));  // -1
  }

  TEST_CASE("a strict enumeration with its components holds one of them, any other enumeration any value") {
    CHECK(valid<E_Mode>({5, 0}));
    CHECK(valid<E_Mode>({1, 0}));
    CHECK_FALSE(valid<E_Mode>({2, 0}));
    CHECK(valid<E_Loose>({7, 0}));  // CODESYS keeps a number that names no component
  }

  TEST_CASE("ARRAY and STRUCT: every element and member") {
    CHECK(valid<ARRAY<BOOL, 1, 3>>({1, 0, 1}));
    CHECK_FALSE(valid<ARRAY<BOOL, 1, 3>>({1, 0, 3}));
    CHECK_FALSE(valid<std::array<BOOL, 2>>({2, 0}));
    CHECK_FALSE(valid<BOOL[2]>({0, 9}));
    ST_Flags flags{TRUE, 7, "ab"};
    auto raw = bytes_of(flags);
    CHECK(detail::valid_value_bytes<ST_Flags>(raw.data()));
    raw[offsetof(ST_Flags, bOn)] = std::byte{2};
    CHECK_FALSE(detail::valid_value_bytes<ST_Flags>(raw.data()));
    raw = bytes_of(flags);
    raw[offsetof(ST_Flags, nCount)] = std::byte{200};  // USINT: any byte
    CHECK(detail::valid_value_bytes<ST_Flags>(raw.data()));
    std::memset(raw.data() + offsetof(ST_Flags, sName), 'x', sizeof(STRING<4>));
    CHECK_FALSE(detail::valid_value_bytes<ST_Flags>(raw.data()));
    CHECK(valid<ARRAY<ST_Flags, 0, 1>>({}));  // zeros: FALSE, 0, ''
  }

  TEST_CASE("integers, REAL, TIME take every pattern") {
    CHECK(valid<INT>({0xFF, 0xFF}));
    CHECK(valid<REAL>({0xFF, 0xFF, 0xFF, 0xFF}));  // a NaN is a REAL
    CHECK(valid<TIME>({0xFF, 0xFF, 0xFF, 0xFF}));
  }
}

// --- A STRUCT's type hash covers its members ---------------------------------------------

namespace {
struct ST_Counter {
  USINT nValue;
  INT iLimit;
};
}  // namespace

TEST_CASE("retain: a STRUCT's type hash is its name with each member's name and type") {
  // A new download that retypes ST_Counter.nValue from USINT to BOOL keeps the STRUCT's name
  // and size; its hash changes with the member's type (and so the image's layout hash).
  const auto hash_with = [](std::string_view members) {
    detail::fnv1a hash;
    hash.add(detail::type_name<ST_Counter>()).add(members);
    return hash.value();
  };
  CHECK(detail::type_hash<ST_Counter> == hash_with("{nValue:USINT;iLimit:INT;}"));
  CHECK(detail::type_hash<ST_Counter> != hash_with("{nValue:BOOL;iLimit:INT;}"));
  CHECK(detail::type_hash<ST_Counter> != hash_with(""));
  CHECK(detail::type_hash<ARRAY<ST_Counter, 1, 2>> != detail::type_hash<ARRAY<ST_Flags, 1, 2>>);
}

// --- Images with invalid values are not restored -------------------------------------------

namespace {

struct object_with_values {
  retain<BOOL> bFlag;
  retain<STRING<8>> sName;
  persistent<INT> iKept{INT(3)};
};

template <class T>
std::array<detail::retained_object, 1> objects_of(const T& object) {
  return {detail::retained_object{&object, sizeof(T)}};
}

/// Rewrites the image's checksum after a change, as a crafted image would carry it.
void reseal(std::span<std::byte> image) {
  const std::size_t total = detail::retained_get(image.data() + 8, 4);
  detail::retained_put(image.data() + 12, detail::retained_checksum(image.subspan(16, total - 16)), 4);
}

}  // namespace

TEST_SUITE("retain: a checked image") {
  TEST_CASE("a BOOL of 2 or a STRING(8) of LEN 9 with a correct checksum is not restored") {
    object_with_values saved;
    saved.bFlag = TRUE;
    saved.sName = STRING<8>("pump");
    saved.iKept = 9;
    std::array<std::byte, 256> image{};
    const std::size_t size = detail::save_retained(objects_of(saved), retain_kinds::both, image);
    REQUIRE(size > 0);
    // The RETAIN section's values start after the 16-byte header and the 16-byte section header.
    const std::size_t values = 32;

    SUBCASE("BOOL") { image[values] = std::byte{2}; }
    SUBCASE("STRING") { std::memset(image.data() + values + 1, 'x', sizeof(STRING<8>)); }
    reseal(image);
    REQUIRE(detail::valid_retained_image(std::span(image).first(size)));

    object_with_values loaded;
    const auto verdict = detail::check_retained(objects_of(loaded), retain_kinds::both, std::span(image).first(size));
    CHECK(verdict.retain == retain_load::invalid_value);
    CHECK(verdict.persistent == retain_load::restored);
    CHECK(detail::restore_checked(objects_of(loaded), verdict, std::span(image).first(size)) ==
          retain_kinds::persistent);
    CHECK(loaded.bFlag == FALSE);  // the initial values, whole: no value of the section is taken
    CHECK(loaded.sName.get().view() == "");
    CHECK(loaded.iKept == 9);
    CHECK((loaded.bFlag != !loaded.bFlag));
  }

  TEST_CASE("check_retained names each reason") {
    object_with_values saved;
    std::array<std::byte, 256> image{};
    const std::size_t size = detail::save_retained(objects_of(saved), retain_kinds::retain, image);
    object_with_values loaded;
    auto verdict = detail::check_retained(objects_of(loaded), retain_kinds::both, std::span(image).first(size));
    CHECK(verdict.retain == retain_load::restored);
    CHECK(verdict.persistent == retain_load::initial);  // the image has no PERSISTENT section
    verdict = detail::check_retained(objects_of(loaded), retain_kinds::persistent, std::span(image).first(size));
    CHECK(verdict.retain == retain_load::not_kept);
    image[5] = std::byte{9};  // version 2305
    verdict = detail::check_retained(objects_of(loaded), retain_kinds::both, std::span(image).first(size));
    CHECK(verdict.retain == retain_load::damaged);
    CHECK(verdict.persistent == retain_load::damaged);
    struct other_layout {
      retain<INT> bFlag;
    } other;
    image[5] = std::byte{0};
    verdict = detail::check_retained(objects_of(other), retain_kinds::both, std::span(image).first(size));
    CHECK(verdict.retain == retain_load::changed);
  }
}

// --- What start() does with the storage's image ----------------------------------------------

namespace {

std::string events;

// A block that reports the bInitRetains its FB_Init gets, and what retain_info() says then;
// its RETAIN counter is of type Count (DINT, or LINT after a retyping download).
template <class Count>
struct FB_Counting : function_block<FB_Counting<Count>> {
  FB_Counting() { run_fb_init(*this); }
  retain<Count> nCount;

 private:
  friend struct iecoop::block_access;
  BOOL FB_Init(BOOL bInitRetains, BOOL /*bInCopyCode*/) {
    events +=
        std::string("init:") + (bInitRetains ? "T" : "F") + ":" + std::string(to_string(retain_info().retain)) + " ";
    return TRUE;
  }
};
using FB_Counter = FB_Counting<DINT>;

// PROGRAM PRG_Line: a counter, a RETAIN flag and name, a PERSISTENT total
struct PRG_Line : program<PRG_Line> {
  FB_Counter fbCounter;
  retain<BOOL> bRunning;
  retain<STRING<8>> sBatch;
  persistent<UDINT> nTotal{100U};
  void body() {
    fbCounter.nCount = fbCounter.nCount + 1;
    nTotal = nTotal + 1U;
    bRunning = TRUE;
    sBatch = STRING<8>("B-42");
  }
};

// The same program after a new download that retyped a variable (DINT -> LINT in the block).
struct PRG_Line2 : program<PRG_Line2> {
  FB_Counting<LINT> fbCounter;
  retain<BOOL> bRunning;
  retain<STRING<8>> sBatch;
  persistent<UDINT> nTotal{100U};
  void body() {}
};

LTIME ms(std::uint64_t n) { return LTIME::from_ticks(n * 1000000U); }

auto make_line() { return application{task<PRG_Line>{"Main", cyclic{"T#1ms"_iec}, 1}}; }
auto make_line2() { return application{task<PRG_Line2>{"Main", cyclic{"T#1ms"_iec}, 1}}; }

/// A storage with the optional members: the image saved before the last (load_previous) and
/// set_aside, as file_storage has them, in memory.
struct two_slot_storage {
  std::array<std::byte, 512> current{};
  std::size_t current_size = 0;
  std::array<std::byte, 512> previous{};
  std::size_t previous_size = 0;
  std::array<std::byte, 512> aside{};
  std::size_t aside_size = 0;
  int set_asides = 0;

  bool save(std::span<const std::byte> data) {
    previous = current;
    previous_size = current_size;
    std::copy(data.begin(), data.end(), current.begin());
    current_size = data.size();
    return true;
  }
  std::size_t load(std::span<std::byte> buffer) const {
    if (current_size == 0 || buffer.size() < current_size) return 0;
    std::copy_n(current.begin(), current_size, buffer.begin());
    return current_size;
  }
  std::size_t load_previous(std::span<std::byte> buffer) const {
    if (previous_size == 0 || buffer.size() < previous_size) return 0;
    std::copy_n(previous.begin(), previous_size, buffer.begin());
    return previous_size;
  }
  bool set_aside() {
    aside = current;
    aside_size = current_size;
    current_size = 0;
    ++set_asides;
    return true;
  }
  [[nodiscard]] std::size_t stored_size() const { return current_size; }
  [[nodiscard]] std::span<std::byte> bytes() { return std::span(current).first(current_size); }
};

/// Runs the line for a few cycles and stops it twice, so that the storage holds two images
/// (the previous with nTotal 103, the current with 106).
void run_twice(two_slot_storage& storage) {
  auto plc = make_line();
  plc.use_storage(storage);
  plc.start();
  plc.run_for(ms(3));
  plc.stop();
  plc.start();
  plc.run_for(ms(3));
  plc.stop();
}

}  // namespace

TEST_SUITE("application: what start() finds in the storage") {
  TEST_CASE("an intact image: restored, bInitRetains = FALSE, and FB_Init already sees the status") {
    two_slot_storage storage;
    run_twice(storage);
    auto plc = make_line();
    plc.use_storage(storage);
    events.clear();
    REQUIRE(plc.start());
    CHECK(events == "init:F:restored ");  // once: the probe of the layout runs no FB_Init
    CHECK(plc.retain_status().retain == retain_load::restored);
    CHECK(plc.retain_status().persistent == retain_load::restored);
    CHECK(plc.retain_status().BootDataLoaded);
    CHECK_FALSE(plc.retain_status().OldBootData);
    CHECK_FALSE(plc.retain_status().rejected());
    CHECK(retain_info() == plc.retain_status());
    CHECK(PRG_Line::instance().nTotal == 106U);
    CHECK(PRG_Line::instance().fbCounter.nCount == 6);
    CHECK(storage.set_asides == 0);
  }

  TEST_CASE("a first start finds nothing: initial") {
    two_slot_storage storage;
    auto plc = make_line();
    plc.use_storage(storage);
    events.clear();
    plc.start();
    CHECK(events == "init:T:initial ");
    CHECK(plc.retain_status().retain == retain_load::initial);
    CHECK(plc.retain_status().persistent == retain_load::initial);
    CHECK_FALSE(plc.retain_status().BootDataLoaded);
  }

  TEST_CASE("a damaged image: the previous one is restored (OldBootData), the damaged one set aside") {
    two_slot_storage storage;
    run_twice(storage);
    std::array<std::byte, 512> damaged{};
    std::size_t damaged_size = storage.current_size;
    SUBCASE("a flipped byte") { storage.bytes()[storage.current_size - 1] ^= std::byte{0x10}; }
    SUBCASE("truncated") {
      storage.current_size -= 3;
      damaged_size -= 3;
    }
    SUBCASE("another version") { storage.bytes()[4] = std::byte{7}; }
    SUBCASE("junk after the image") {
      storage.current[storage.current_size] = std::byte{'j'};
      storage.current_size += 1;
      damaged_size += 1;
    }
    SUBCASE("not an image") { std::fill(storage.current.begin(), storage.current.end(), std::byte{'x'}); }
    damaged = storage.current;
    auto plc = make_line();
    plc.use_storage(storage);
    events.clear();
    REQUIRE(plc.start());
    CHECK(events == "init:F:restored_previous ");
    CHECK(plc.retain_status().retain == retain_load::restored_previous);
    CHECK(plc.retain_status().persistent == retain_load::restored_previous);
    CHECK(plc.retain_status().BootDataLoaded);
    CHECK(plc.retain_status().OldBootData);
    CHECK(plc.retain_status().set_aside);
    CHECK(PRG_Line::instance().nTotal == 103U);
    CHECK(PRG_Line::instance().fbCounter.nCount == 3);
    // The damaged image is aside, unchanged; the next save does not overwrite it.
    REQUIRE(storage.set_asides == 1);
    CHECK(storage.aside_size == damaged_size);
    CHECK(std::equal(damaged.begin(), damaged.begin() + static_cast<std::ptrdiff_t>(damaged_size),
                     storage.aside.begin()));
    plc.stop();
    CHECK(std::equal(damaged.begin(), damaged.begin() + static_cast<std::ptrdiff_t>(damaged_size),
                     storage.aside.begin()));
  }

  TEST_CASE("a damaged image without a previous one: initial values, bInitRetains = TRUE, damaged") {
    memory_storage<512> storage;
    {
      auto plc = make_line();
      plc.use_storage(storage);
      plc.start();
      plc.run_for(ms(3));
    }
    std::array<std::byte, 512> bytes{};
    const std::size_t size = storage.size();
    std::copy(storage.data().begin(), storage.data().end(), bytes.begin());
    bytes[20] ^= std::byte{1};
    storage.clear();  // no previous image
    REQUIRE(storage.save(std::span(bytes).first(size)));
    auto plc = make_line();
    plc.use_storage(storage);
    events.clear();
    plc.start();
    CHECK(events == "init:T:damaged ");
    CHECK(plc.retain_status().retain == retain_load::damaged);
    CHECK(plc.retain_status().persistent == retain_load::damaged);
    CHECK_FALSE(plc.retain_status().BootDataLoaded);
    CHECK(plc.retain_status().set_aside);
    CHECK(plc.retain_status().rejected());
    CHECK(PRG_Line::instance().nTotal == 100U);
    // The damaged image is aside, unchanged, also after the next save.
    plc.stop();
    REQUIRE(storage.rejected().size() == size);
    CHECK(std::equal(storage.rejected().begin(), storage.rejected().end(), bytes.begin()));
  }

  TEST_CASE("an image of other variables (a new download that retyped one): changed, bInitRetains = TRUE") {
    two_slot_storage storage;
    run_twice(storage);
    auto plc = make_line2();
    plc.use_storage(storage);
    events.clear();
    SUBCASE("restart") {
      plc.start();
      CHECK(events == "init:T:changed ");
      CHECK(plc.retain_status().retain == retain_load::changed);
    }
    SUBCASE("new download") {
      plc.start(start_mode::download);
      CHECK(events == "init:T:not_kept ");
      CHECK(plc.retain_status().retain == retain_load::not_kept);
    }
    // The PERSISTENT variables did not change, but their section's layout hash covers the
    // objects (one program) in which the retyped RETAIN variable moved nothing: kept.
    CHECK(plc.retain_status().persistent == retain_load::restored);
    CHECK(PRG_Line2::instance().nTotal == 106U);
    CHECK(PRG_Line2::instance().fbCounter.nCount == 0);
    CHECK(storage.set_asides == (plc.retain_status().retain == retain_load::changed ? 1 : 0));
  }

  TEST_CASE("an image with a BOOL of 2: invalid_value, nothing of that kind restored, set aside") {
    two_slot_storage storage;
    run_twice(storage);
    // PRG_Line's RETAIN section: fbCounter.nCount (4 bytes), then bRunning.
    std::span<std::byte> image = storage.bytes();
    REQUIRE(image[32 + 4] == std::byte{1});
    image[32 + 4] = std::byte{2};
    reseal(image);
    auto plc = make_line();
    plc.use_storage(storage);
    events.clear();
    plc.start();
    CHECK(events == "init:T:invalid_value ");
    CHECK(plc.retain_status().retain == retain_load::invalid_value);
    CHECK(plc.retain_status().persistent == retain_load::restored);
    CHECK(PRG_Line::instance().bRunning == FALSE);
    CHECK(PRG_Line::instance().fbCounter.nCount == 0);
    CHECK(storage.set_asides == 1);
  }

  TEST_CASE(
      "an image larger than the retain memory: the previous one if intact, else too_large, never dropped silently") {
    two_slot_storage storage;
    run_twice(storage);
    storage.current_size = 400;  // larger than the application's 128 bytes
    bool with_previous = true;
    SUBCASE("with an intact previous image") {}
    SUBCASE("without a previous image") {
      storage.previous_size = 0;
      with_previous = false;
    }
    application plc{task<PRG_Line>{"Main", cyclic{"T#1ms"_iec}, 1}, retain_capacity<128>{}};
    plc.use_storage(storage);
    plc.start();
    const retain_load expect = with_previous ? retain_load::restored_previous : retain_load::too_large;
    CHECK(plc.retain_status().retain == expect);
    CHECK(plc.retain_status().persistent == expect);
    CHECK(plc.retain_status().OldBootData == BOOL(with_previous));
    CHECK(PRG_Line::instance().nTotal == (with_previous ? 103U : 100U));
    CHECK(storage.set_asides == 1);  // the large image is kept aside either way
    CHECK(storage.aside_size == 400);
  }

  TEST_CASE("no current image beside an intact previous one: restored_previous, nothing set aside") {
    two_slot_storage storage;
    run_twice(storage);
    storage.current_size = 0;  // load() finds nothing
    auto plc = make_line();
    plc.use_storage(storage);
    events.clear();
    REQUIRE(plc.start());
    CHECK(events == "init:F:restored_previous ");
    CHECK(plc.retain_status().retain == retain_load::restored_previous);
    CHECK(plc.retain_status().persistent == retain_load::restored_previous);
    CHECK(plc.retain_status().OldBootData);
    CHECK_FALSE(plc.retain_status().set_aside);
    CHECK(storage.set_asides == 0);
    CHECK(PRG_Line::instance().nTotal == 103U);
  }

  TEST_CASE("a warm and a cold reset report what they kept") {
    auto plc = make_line();
    plc.start();
    plc.run_for(ms(2));
    plc.reset(reset_kind::warm);
    CHECK(plc.retain_status().retain == retain_load::restored);
    CHECK(plc.retain_status().persistent == retain_load::restored);
    plc.reset(reset_kind::cold);
    CHECK(plc.retain_status().retain == retain_load::not_kept);
    CHECK(plc.retain_status().persistent == retain_load::restored);
    plc.reset(reset_kind::origin);
    CHECK(plc.retain_status().persistent == retain_load::not_kept);
    CHECK_FALSE(plc.retain_status().BootDataLoaded);
  }
}

namespace {

std::vector<char> read_file(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

void write_file(const std::string& path, const std::vector<char>& bytes) {
  std::ofstream out(path, std::ios::binary | std::ios::trunc);
  out.write(bytes.data(), static_cast<std::streamsize>(bytes.size()));
}

/// A retain file of its own in the temporary directory, with its .previous and .rejected.
struct retain_file {
  std::string path = (std::filesystem::temp_directory_path() /
                      ("iecoop_retain_load_test_" + std::to_string(std::random_device{}()) + ".bin"))
                         .string();
  retain_file() { remove(); }
  ~retain_file() { remove(); }
  retain_file(const retain_file&) = delete;
  retain_file& operator=(const retain_file&) = delete;
  void remove() const {
    std::error_code ignored;
    for (const char* suffix : {"", ".previous", ".rejected"}) std::filesystem::remove(path + suffix, ignored);
  }
};

}  // namespace

TEST_CASE("application: a damaged, empty, missing or too large retain file, with file_storage") {
  retain_file file;
  {
    file_storage storage(file.path.c_str());
    auto plc = make_line();
    plc.use_storage(storage);
    plc.start();
    plc.run_for(ms(3));
    plc.stop();  // the previous image: nTotal 103
    plc.start();
    plc.run_for(ms(3));
    plc.stop();  // the current one: nTotal 106
  }
  const std::vector<char> good = read_file(file.path);
  const std::vector<char> previous = read_file(file.path + ".previous");
  REQUIRE(good.size() > 40);
  REQUIRE(previous.size() == good.size());
  std::vector<char> damaged = good;
  bool missing = false;
  bool set_aside = true;  // the current file is moved to .rejected
  SUBCASE("one flipped bit") { damaged[damaged.size() / 2] ^= 0x04; }
  SUBCASE("truncated") { damaged.resize(damaged.size() - 1); }
  SUBCASE("cut to its header") { damaged.resize(16); }
  SUBCASE("another format version") { damaged[4] = 2; }
  SUBCASE("junk after the image") { damaged.insert(damaged.end(), {'j', 'u', 'n', 'k'}); }
  SUBCASE("larger than the retain memory") { damaged.resize(4096, '\0'); }
  SUBCASE("empty (its data lost, or truncated: `: > retain.bin`)") {
    damaged.clear();
    set_aside = false;  // nothing in it to keep: .rejected is not overwritten with nothing
  }
  SUBCASE("missing") {
    missing = true;
    set_aside = false;
  }
  if (missing) {
    std::filesystem::remove(file.path);
  } else {
    write_file(file.path, damaged);
  }
  file_storage storage(file.path.c_str());
  auto plc = make_line();
  plc.use_storage(storage);
  events.clear();
  REQUIRE(plc.start());
  // Every case: the previous image, intact, is restored and said to be (TwinCAT's OldBootData).
  CHECK(plc.retain_status().retain == retain_load::restored_previous);
  CHECK(plc.retain_status().persistent == retain_load::restored_previous);
  CHECK(events == "init:F:restored_previous ");
  CHECK(PRG_Line::instance().nTotal == 103U);
  CHECK(plc.retain_status().OldBootData);
  CHECK(plc.retain_status().set_aside == set_aside);
  plc.run_for(ms(3));  // nTotal 106 again, from the restored 103
  if (set_aside) {
    // Set aside, byte for byte, and kept over the next save.
    CHECK(read_file(file.path + ".rejected") == damaged);
    plc.stop();
    CHECK(read_file(file.path + ".rejected") == damaged);
  } else {
    CHECK_FALSE(std::filesystem::exists(file.path + ".rejected"));
    plc.stop();
  }
  // The generation restored is not lost by the save after it: the new image is at <path>, and
  // <path>.previous still holds the image restored (an empty or missing file never became it).
  CHECK(read_file(file.path + ".previous") == previous);
  file_storage again(file.path.c_str());
  auto next = make_line();
  next.use_storage(again);
  REQUIRE(next.start());
  CHECK(next.retain_status().retain == retain_load::restored);
  CHECK(PRG_Line::instance().nTotal == 106U);
  next.stop();
}

TEST_CASE("application: only a storage with neither a current nor a previous image is a first start") {
  retain_file file;
  {
    file_storage storage(file.path.c_str());
    auto plc = make_line();
    plc.use_storage(storage);
    plc.start();
    plc.run_for(ms(3));
    plc.stop();  // one image, no previous
  }
  std::vector<char> damaged = read_file(file.path);
  SUBCASE("empty, no previous") { damaged.clear(); }
  SUBCASE("damaged, no previous") { damaged[damaged.size() / 2] ^= 0x04; }
  const bool empty = damaged.empty();
  write_file(file.path, damaged);
  file_storage storage(file.path.c_str());
  auto plc = make_line();
  plc.use_storage(storage);
  events.clear();
  REQUIRE(plc.start());
  const std::string expect = empty ? "initial" : "damaged";
  CHECK(std::string(to_string(plc.retain_status().retain)) == expect);
  CHECK(events == "init:T:" + expect + " ");
  CHECK(PRG_Line::instance().nTotal == 100U);
  CHECK(plc.retain_status().set_aside == !empty);
  plc.stop();
}

TEST_SUITE("application: the retain memory is checked at start") {
  TEST_CASE("RETAIN data larger than the retain memory: start() fails with a fault, nothing runs or is lost later") {
    fault_recorder faults;
    application plc{task<PRG_Line>{"Main", cyclic{"T#1ms"_iec}, 1}, retain_capacity<40>{}};
    events.clear();
    CHECK_FALSE(plc.start());
    CHECK(faults.count == 1);
    CHECK(faults.last_kind == fault_kind::invalid_value);
    CHECK(faults.last_message.find("retain_capacity") != std::string::npos);
    CHECK(plc.state() == application_state::stopped);
    CHECK_FALSE(PRG_Line::exists());
    CHECK(plc.retain_bytes_needed() > 40);
    CHECK(events == "init:T:initial ");  // constructed, found too big, ended
    // With the memory it names, it starts.
    application enough{task<PRG_Line>{"Main", cyclic{"T#1ms"_iec}, 1}, retain_capacity<128>{}};
    CHECK(plc.retain_bytes_needed() <= 128);
    CHECK(enough.start());
    CHECK(faults.count == 1);
  }

  TEST_CASE("a storage that fails to save reports its fault after FB_Exit has run") {
    struct failing_storage {
      bool save(std::span<const std::byte>) { return false; }
      std::size_t load(std::span<std::byte>) { return 0; }
    } storage;
    static bool exited_before_fault = false;
    static bool exited = false;
    struct PRG_Exit : program<PRG_Exit> {
      PRG_Exit() { run_fb_init(*this); }
      ~PRG_Exit() { run_fb_exit(*this); }
      PRG_Exit(const PRG_Exit&) = default;
      PRG_Exit& operator=(const PRG_Exit&) = default;
      retain<INT> iValue;
      void body() {}

     private:
      friend struct iecoop::block_access;
      BOOL FB_Init(BOOL, BOOL) { return TRUE; }
      BOOL FB_Exit(BOOL) {
        exited = true;
        return TRUE;
      }
    };
    const fault_handler previous = set_fault_handler([](const fault_info&) { exited_before_fault = exited; });
    {
      application plc{task<PRG_Exit>{"Main", cyclic{"T#1ms"_iec}, 1}};
      plc.use_storage(storage);
      plc.start();
      plc.stop();
    }
    set_fault_handler(previous);
    CHECK(exited);
    CHECK(exited_before_fault);
  }
}
