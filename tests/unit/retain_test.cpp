// RETAIN and PERSISTENT variables: their registration, the image the scheduler saves and
// restores over resets and restarts, layout changes, and memory_storage.
#include "iecoop_test.hpp"

#include <iecoop/runtime/retain.hpp>

#include <array>
#include <cstddef>
#include <cstring>
#include <memory>
#include <span>

using namespace iecoop;
using iecoop::detail::retained_object;

namespace {

// A STRUCT, kept as a whole.
struct ST_Recipe {
  INT iSpeed;
  REAL rRamp;
};

// FUNCTION_BLOCK FB_Counter  VAR RETAIN diTotal : DINT := 100; END_VAR  VAR iCalls : INT; END_VAR
struct FB_Counter : function_block<FB_Counter> {
  retain<DINT> diTotal{100};
  INT iCalls;
  void body() {
    diTotal += 1;
    iCalls = iCalls + 1;
  }
};

// PROGRAM PRG_Machine, with normal, RETAIN and PERSISTENT variables and a block inside.
struct PRG_Machine : program<PRG_Machine> {
  INT iCycles = 3;                       // VAR iCycles : INT := 3;
  retain<INT> iCount{5};                 // VAR RETAIN iCount : INT := 5;
  retain<REAL> rLast{1.5};               //   rLast : REAL := 1.5;
  retain<BOOL> bHomed;                   //   bHomed : BOOL;
  persistent<TIME> tRuntime;             // VAR PERSISTENT tRuntime : TIME;
  persistent<STRING<10>> sName{"init"};  //   sName : STRING(10) := 'init';
  persistent<DINT> diSerial{7};          //   diSerial : DINT := 7;
  FB_Counter counter;                    // VAR counter : FB_Counter; (its diTotal is RETAIN)
  persistent<ST_Recipe> stRecipe;        // VAR PERSISTENT stRecipe : ST_Recipe;
  void body() {
    iCycles = iCycles + 1;
    iCount = iCount + 1;
    counter();
  }
};

void change_everything(PRG_Machine& m) {
  m.iCycles = 11;
  m.iCount = 42;
  m.rLast = 2.25;
  m.bHomed = TRUE;
  m.tRuntime = "T#1h2m"_iec;
  m.sName = "conveyor";
  m.diSerial = 123456;
  m.counter();
  m.counter();  // diTotal 102, iCalls 2
  m.stRecipe.ref().iSpeed = 300;
  m.stRecipe.ref().rRamp = 0.5;
}

void check_retain_kept(const PRG_Machine& m) {
  CHECK(m.iCount == 42);
  CHECK(m.rLast == 2.25);
  CHECK(m.bHomed == TRUE);
  CHECK(m.counter.diTotal == 102);
}
void check_retain_initial(const PRG_Machine& m) {
  CHECK(m.iCount == 5);
  CHECK(m.rLast == 1.5);
  CHECK(m.bHomed == FALSE);
  CHECK(m.counter.diTotal == 100);
}
void check_persistent_kept(const PRG_Machine& m) {
  CHECK(m.tRuntime == "T#1h2m"_iec);
  CHECK(m.sName == "conveyor");
  CHECK(m.diSerial == 123456);
  CHECK(m.stRecipe->iSpeed == 300);
  CHECK(m.stRecipe->rRamp == 0.5);
}
void check_persistent_initial(const PRG_Machine& m) {
  CHECK(m.tRuntime == "T#0ms"_iec);
  CHECK(m.sName == "init");
  CHECK(m.diSerial == 7);
  CHECK(m.stRecipe->iSpeed == 0);
  CHECK(m.stRecipe->rRamp == 0.0);
}
void check_normal_initial(const PRG_Machine& m) {
  CHECK(m.iCycles == 3);
  CHECK(m.counter.iCalls == 0);
}

template <class T>
retained_object object_of(T& instance) {
  return {&instance, sizeof instance};
}

/// Every variable in the list, whatever object it lies in.
std::size_t listed_variables() {
  std::size_t n = 0;
  for (const detail::retained_node* node = detail::retained_first; node != nullptr; node = node->next) ++n;
  return n;
}

/// What the scheduler does for `event`: save the kinds kept, rebuild the instance in place
/// (FB_Exit, then construction and FB_Init), restore. Returns the kinds restored.
template <class T>
retain_kinds rebuild(T& instance, retain_event event) {
  const retained_object objects[] = {object_of(instance)};
  const retain_kinds kinds = kept_over(event);
  std::array<std::byte, 512> image{};
  const std::size_t size = detail::save_retained(objects, kinds, image);
  REQUIRE(size == detail::retained_image_size(objects, kinds));
  std::destroy_at(&instance);
  std::construct_at(&instance);
  return detail::restore_retained(objects, kinds, std::span(image).first(size));
}

// The same program one download later, with its declarations changed.
struct PRG_OneMore : function_block<PRG_OneMore> {  // one more RETAIN variable
  INT iCycles = 3;
  retain<INT> iCount{5};
  retain<REAL> rLast{1.5};
  retain<BOOL> bHomed;
  persistent<TIME> tRuntime;
  persistent<STRING<10>> sName{"init"};
  persistent<DINT> diSerial{7};
  FB_Counter counter;
  persistent<ST_Recipe> stRecipe;
  retain<INT> iAdded{9};
  void body() {}
};
struct PRG_Retyped : function_block<PRG_Retyped> {  // diSerial : UDINT, same size
  INT iCycles = 3;
  retain<INT> iCount{5};
  retain<REAL> rLast{1.5};
  retain<BOOL> bHomed;
  persistent<TIME> tRuntime;
  persistent<STRING<10>> sName{"init"};
  persistent<UDINT> diSerial{7U};
  FB_Counter counter;
  persistent<ST_Recipe> stRecipe;
  void body() {}
};

// Two small blocks of the same layout.
struct FB_Axis : function_block<FB_Axis> {
  retain<LREAL> lrPosition;
  persistent<WORD> wConfig;
  void body() {}
};

// A global variable list: VAR_GLOBAL RETAIN ... END_VAR as a struct, declared globally.
struct GVL_Retain {
  retain<UDINT> udiStarts;
  persistent<LTIME> ltTotal;
};
GVL_Retain gvl;

// A block with FB_Init, to see what FB_Init sees during a warm reset.
struct FB_WithInit : function_block<FB_WithInit> {
  FB_WithInit() { run_fb_init(*this); }
  retain<INT> iKept{1};
  INT iSeen;
  BOOL bSeenInitRetains;
  void body() {}
  BOOL FB_Init(BOOL bInitRetains, BOOL) {
    iSeen = iKept;
    bSeenInitRetains = bInitRetains;
    return TRUE;
  }
};

// VAR_INPUT RETAIN / VAR_OUTPUT PERSISTENT: remanent variables as pins of a call.
struct FB_Pins : function_block<FB_Pins> {
  retain<INT> iSetpoint;
  persistent<DINT> diResult;
  using VAR_INPUT = pins<&FB_Pins::iSetpoint>;
  using VAR_OUTPUT = pins<&FB_Pins::diResult>;
  void body() { diResult = iSetpoint + DINT(1); }
};

alignas(std::max_align_t) std::array<std::byte, 4096> image_buffer{};

}  // namespace

TEST_SUITE("retain") {
  TEST_CASE("retain<> and persistent<> read and write like their value") {
    retain<INT> iCount{5};
    iCount = iCount + 1;
    CHECK(iCount == 6);
    iCount += 4;
    ++iCount;
    CHECK(iCount.get() == 11);
    --iCount;
    iCount -= 2;
    iCount *= 3;
    iCount /= 2;
    CHECK(iCount == 12);
    const INT plain = iCount;
    CHECK(plain == 12);

    persistent<BOOL> bFlag;
    CHECK(!bFlag);
    bFlag = TRUE;
    CHECK(static_cast<bool>(bFlag));

    persistent<REAL> rValue{0.5};
    CHECK(rValue * 2.0 == 1.0);

    retain<STRING<10>> sText{"abc"};
    CHECK(sText == "abc");
    sText = "a longer text than ten";
    CHECK(sText->size() == 10);

    retain<ST_Recipe> stRecipe;
    stRecipe.ref().iSpeed = 7;
    stRecipe->rRamp = 1.5;
    CHECK(stRecipe.get().iSpeed == 7);
    CHECK(stRecipe->rRamp == 1.5);

    static_assert(detail::value_wrapper<retain<INT>>);
    static_assert(detail::value_wrapper<persistent<INT>>);
    static_assert(std::is_same_v<decltype(iCount = 1), retain<INT>&>);
    static_assert(std::is_same_v<decltype(rValue += 1.0), persistent<REAL>&>);
  }

  TEST_CASE("remanent variables are pins of a call like any variable") {
    FB_Pins fb;
    DINT result;
    fb("iSetpoint"_ = INT(41), "diResult"_ >> result);
    CHECK(result == 42);
    CHECK(fb.iSetpoint == 41);
  }

  TEST_CASE("the kinds kept over each event follow CODESYS's table") {
    static_assert(kept_over(retain_event::warm_reset) == retain_kinds::both);
    static_assert(kept_over(retain_event::cold_reset) == retain_kinds::persistent);
    static_assert(kept_over(retain_event::origin_reset) == retain_kinds::none);
    static_assert(kept_over(retain_event::download) == retain_kinds::persistent);
    static_assert(kept_over(retain_event::restart) == retain_kinds::both);
    static_assert((retain_kind::retain | retain_kind::persistent) == retain_kinds::both);
    static_assert(retain_kinds::both.contains(retain_kind::retain));
    static_assert(!retain_kinds::persistent.contains(retain_kind::retain));
    static_assert(retain_kinds::none.empty() && retain_kinds{}.empty());
    static_assert((retain_kinds::both & retain_kind::retain) == retain_kinds::retain);
    static_assert(retain_kinds::both.bits() == 3);
  }

  TEST_CASE("types hash under their IEC names") {
    static_assert(detail::type_hash<INT> == detail::fnv1a().add("INT").value());
    static_assert(detail::type_hash<STRING<10>> == detail::fnv1a().add("STRING(10)").value());
    static_assert(detail::type_hash<WSTRING<10>> == detail::fnv1a().add("WSTRING(10)").value());
    static_assert(detail::type_hash<std::array<INT, 3>> == detail::fnv1a().add("ARRAY[3] OF INT").value());
    static_assert(detail::type_hash<ARRAY<INT, 1, 3>> == detail::fnv1a().add("ARRAY[1..3] OF INT").value());
    static_assert(detail::type_hash<ARRAY<INT, -1, 1, 0, 2>> ==
                  detail::fnv1a().add("ARRAY[-1..1,0..2] OF INT").value());
    static_assert(detail::type_hash<ARRAY<INT, 0, 2>> != detail::type_hash<ARRAY<INT, 1, 3>>);
    static_assert(detail::type_hash<INT> != detail::type_hash<UINT>);
    static_assert(detail::type_hash<INT> != detail::type_hash<WORD>);
    static_assert(detail::type_hash<STRING<10>> != detail::type_hash<STRING<11>>);
    static_assert(detail::type_hash<TIME> != detail::type_hash<UDINT>);
    static_assert(detail::type_name<ST_Recipe>().ends_with("ST_Recipe"));
    CHECK(detail::type_name<ST_Recipe>().find("ST_Recipe") != std::string_view::npos);
  }

  TEST_CASE("variables enter the list at construction and copy construction and leave it at destruction") {
    const std::size_t before = listed_variables();
    {
      retain<INT> a{1};
      CHECK(listed_variables() == before + 1);
      {
        persistent<INT> b{2};
        retain<INT> copy = a;  // a variable of its own
        CHECK(listed_variables() == before + 3);
        const retained_object objects[] = {object_of(copy)};
        CHECK(detail::retained_count(objects, retain_kinds::both) == 1);
        CHECK(detail::retained_count(objects, retain_kinds::persistent) == 0);
        copy = retain<INT>{9};  // a temporary: enters and leaves the list; copies the value only
        CHECK(copy == 9);
        CHECK(listed_variables() == before + 3);
        CHECK(detail::retained_count(objects, retain_kinds::retain) == 1);
      }
      CHECK(listed_variables() == before + 1);
      {
        PRG_Machine machine;
        CHECK(listed_variables() == before + 1 + 8);
        const retained_object objects[] = {object_of(machine)};
        CHECK(detail::retained_count(objects, retain_kinds::retain) == 4);
        CHECK(detail::retained_count(objects, retain_kinds::persistent) == 4);
      }
      CHECK(listed_variables() == before + 1);
    }
    CHECK(listed_variables() == before);
  }

  TEST_CASE("save and restore: every RETAIN and PERSISTENT value comes back, normal variables do not") {
    PRG_Machine machine;
    change_everything(machine);
    const retained_object objects[] = {object_of(machine)};
    const std::size_t size = detail::save_retained(objects, retain_kinds::both, image_buffer);
    // header, two section headers, INT REAL BOOL DINT | TIME STRING(10) DINT ST_Recipe
    CHECK(size == 16 + 16 + 2 + 4 + 1 + 4 + 16 + 4 + 11 + 4 + sizeof(ST_Recipe));
    CHECK(size == detail::retained_image_size(objects, retain_kinds::both));
    CHECK(size == detail::retained_image_size_needed(objects));  // start()'s check, in one pass

    std::destroy_at(&machine);
    std::construct_at(&machine);
    check_retain_initial(machine);
    check_persistent_initial(machine);

    CHECK(detail::restore_retained(objects, retain_kinds::both, std::span(image_buffer).first(size)) ==
          retain_kinds::both);
    check_retain_kept(machine);
    check_persistent_kept(machine);
    check_normal_initial(machine);
    // Restoring twice changes nothing.
    CHECK(detail::restore_retained(objects, retain_kinds::both, std::span(image_buffer).first(size)) ==
          retain_kinds::both);
    check_retain_kept(machine);
  }

  TEST_CASE("reset warm: RETAIN and PERSISTENT kept") {
    PRG_Machine machine;
    change_everything(machine);
    CHECK(rebuild(machine, retain_event::warm_reset) == retain_kinds::both);
    check_normal_initial(machine);
    check_retain_kept(machine);
    check_persistent_kept(machine);
    CHECK(PRG_Machine::exists());
  }

  TEST_CASE("reset cold: RETAIN re-initialised, PERSISTENT kept") {
    PRG_Machine machine;
    change_everything(machine);
    CHECK(rebuild(machine, retain_event::cold_reset) == retain_kinds::persistent);
    check_normal_initial(machine);
    check_retain_initial(machine);
    check_persistent_kept(machine);
  }

  TEST_CASE("reset origin: everything re-initialised") {
    PRG_Machine machine;
    change_everything(machine);
    CHECK(rebuild(machine, retain_event::origin_reset) == retain_kinds::none);
    check_normal_initial(machine);
    check_retain_initial(machine);
    check_persistent_initial(machine);
  }

  TEST_CASE("new download: RETAIN re-initialised, PERSISTENT kept") {
    PRG_Machine machine;
    change_everything(machine);
    CHECK(rebuild(machine, retain_event::download) == retain_kinds::persistent);
    check_normal_initial(machine);
    check_retain_initial(machine);
    check_persistent_kept(machine);
  }

  TEST_CASE("restart: the image goes through a storage, and both kinds come back in the next run") {
    memory_storage<512> storage;
    static_assert(RetainStorage<memory_storage<512>>);
    {
      PRG_Machine machine;  // the first run
      change_everything(machine);
      const retained_object objects[] = {object_of(machine)};
      const std::size_t size = detail::save_retained(objects, kept_over(retain_event::restart), image_buffer);
      REQUIRE(size > 0);
      CHECK(storage.save(std::span(image_buffer).first(size)));
    }  // the process ends
    std::array<std::byte, 512> loaded{};
    PRG_Machine machine;  // the next run
    const std::size_t size = storage.load(loaded);
    REQUIRE(size == storage.size());
    const retained_object objects[] = {object_of(machine)};
    CHECK(detail::restore_retained(objects, kept_over(retain_event::restart), std::span(loaded).first(size)) ==
          retain_kinds::both);
    check_normal_initial(machine);
    check_retain_kept(machine);
    check_persistent_kept(machine);
  }

  TEST_CASE("lifecycle reset with FB_Init: the kept value is in place when FB_Init runs") {
    FB_WithInit block;
    block.iKept = 77;
    const retained_object objects[] = {object_of(block)};
    const std::size_t size = detail::save_retained(objects, retain_kinds::both, image_buffer);
    const std::span<const std::byte> saved = std::span(image_buffer).first(size);
    SUBCASE("warm: restored as the variables are constructed, FB_Init sees the kept value") {
      const detail::retained_restore_session restoring(objects, retain_kinds::both, saved);
      reset(block, reset_kind::warm);
      CHECK(restoring.finish() == retain_kinds::both);
      CHECK(block.bSeenInitRetains == FALSE);
      CHECK(block.iSeen == 77);  // as in CODESYS (docs/retain.md, "Start-up order")
      CHECK(block.iKept == 77);
    }
    SUBCASE("cold: RETAIN not kept, FB_Init sees the initial value") {
      const detail::retained_restore_session restoring(objects, kept_over(retain_event::cold_reset), saved);
      reset(block, reset_kind::cold);
      CHECK(block.bSeenInitRetains == TRUE);
      CHECK(block.iSeen == 1);
      CHECK(block.iKept == 1);
    }
    SUBCASE("without a session: the values come back only with a restore after construction") {
      reset(block, reset_kind::warm);
      CHECK(block.iSeen == 1);
      CHECK(detail::restore_retained(objects, retain_kinds::both, saved) == retain_kinds::both);
      CHECK(block.iKept == 77);
    }
  }

  TEST_CASE("a RETAIN section whose layout changed is skipped, the PERSISTENT one is still restored") {
    PRG_Machine machine;
    change_everything(machine);
    const retained_object old_objects[] = {object_of(machine)};
    const std::size_t size = detail::save_retained(old_objects, retain_kinds::both, image_buffer);

    PRG_OneMore changed;  // the next version of the program, one RETAIN variable more
    const retained_object objects[] = {object_of(changed)};
    CHECK(detail::restore_retained(objects, retain_kinds::both, std::span(image_buffer).first(size)) ==
          retain_kinds::persistent);
    CHECK(changed.iCount == 5);
    CHECK(changed.counter.diTotal == 100);
    CHECK(changed.iAdded == 9);
    CHECK(changed.diSerial == 123456);
    CHECK(changed.sName == "conveyor");
    CHECK(changed.stRecipe->iSpeed == 300);
  }

  TEST_CASE("a PERSISTENT section with a retyped variable is skipped, the RETAIN one is still restored") {
    PRG_Machine machine;
    change_everything(machine);
    const retained_object old_objects[] = {object_of(machine)};
    const std::size_t size = detail::save_retained(old_objects, retain_kinds::both, image_buffer);

    PRG_Retyped changed;
    static_assert(sizeof(PRG_Retyped) == sizeof(PRG_Machine));
    const retained_object objects[] = {object_of(changed)};
    CHECK(detail::restore_retained(objects, retain_kinds::both, std::span(image_buffer).first(size)) ==
          retain_kinds::retain);
    CHECK(changed.iCount == 42);
    CHECK(changed.counter.diTotal == 102);
    CHECK(changed.diSerial == 7U);
    CHECK(changed.sName == "init");
  }

  TEST_CASE("a variable moved to another object does not match") {
    FB_Axis a;
    FB_Axis b;
    a.lrPosition = 1.0;
    const retained_object both_objects[] = {object_of(a), object_of(b)};
    const std::size_t size = detail::save_retained(both_objects, retain_kinds::both, image_buffer);
    const retained_object swapped[] = {object_of(a)};  // one object fewer
    CHECK(detail::restore_retained(swapped, retain_kinds::both, std::span(image_buffer).first(size)) ==
          retain_kinds::none);
    const retained_object reordered[] = {object_of(b), object_of(a)};  // same layout: values go by position
    a.lrPosition = 5.0;
    CHECK(detail::restore_retained(reordered, retain_kinds::both, std::span(image_buffer).first(size)) ==
          retain_kinds::both);
    CHECK(b.lrPosition == 1.0);
    CHECK(a.lrPosition == 0.0);
  }

  TEST_CASE("variables outside the objects are neither saved nor restored") {
    FB_Axis saved_axis;
    FB_Axis other_axis;
    retain<INT> stray{3};
    saved_axis.lrPosition = 12.5;
    saved_axis.wConfig = WORD(0xF0);
    other_axis.lrPosition = 4.0;
    const retained_object objects[] = {object_of(saved_axis)};
    const std::size_t size = detail::save_retained(objects, retain_kinds::both, image_buffer);
    CHECK(size == 16 + 16 + 8 + 16 + 2);

    saved_axis.lrPosition = 0.0;
    saved_axis.wConfig = WORD(0);
    other_axis.lrPosition = 99.0;
    stray = 4;
    CHECK(detail::restore_retained(objects, retain_kinds::both, std::span(image_buffer).first(size)) ==
          retain_kinds::both);
    CHECK(saved_axis.lrPosition == 12.5);
    CHECK(saved_axis.wConfig == WORD(0xF0));
    CHECK(other_axis.lrPosition == 99.0);
    CHECK(stray == 4);
  }

  TEST_CASE("only the kinds asked for are saved, and only those asked for are restored") {
    PRG_Machine machine;
    change_everything(machine);
    const retained_object objects[] = {object_of(machine)};
    const std::size_t size = detail::save_retained(objects, retain_kinds::both, image_buffer);
    std::destroy_at(&machine);
    std::construct_at(&machine);
    CHECK(detail::restore_retained(objects, retain_kinds::persistent, std::span(image_buffer).first(size)) ==
          retain_kinds::persistent);
    check_retain_initial(machine);
    check_persistent_kept(machine);

    // An image of RETAIN only restores no PERSISTENT.
    change_everything(machine);
    const std::size_t retain_only = detail::save_retained(objects, retain_kinds::retain, image_buffer);
    CHECK(retain_only == detail::retained_image_size(objects, retain_kinds::retain));
    std::destroy_at(&machine);
    std::construct_at(&machine);
    CHECK(detail::restore_retained(objects, retain_kinds::both, std::span(image_buffer).first(retain_only)) ==
          retain_kinds::retain);
    check_retain_kept(machine);
    check_persistent_initial(machine);

    // An image of nothing is a bare header.
    CHECK(detail::save_retained(objects, retain_kinds::none, image_buffer) == 16);
    CHECK(detail::restore_retained(objects, retain_kinds::both, std::span(image_buffer).first(16)) ==
          retain_kinds::none);
  }

  TEST_CASE("objects without remanent variables save empty sections") {
    INT plain;
    const retained_object objects[] = {object_of(plain)};
    const std::size_t size = detail::save_retained(objects, retain_kinds::both, image_buffer);
    CHECK(size == 16 + 16 + 16);
    CHECK(detail::restore_retained(objects, retain_kinds::both, std::span(image_buffer).first(size)) ==
          retain_kinds::both);
    CHECK(detail::save_retained({}, retain_kinds::both, image_buffer) == 48);
  }

  TEST_CASE("a global variable list is an object too") {
    gvl.udiStarts = gvl.udiStarts + 1U;
    gvl.ltTotal = "LTIME#5s"_iec;
    const retained_object objects[] = {object_of(gvl)};
    const std::size_t size = detail::save_retained(objects, retain_kinds::both, image_buffer);
    const UDINT starts = gvl.udiStarts;
    std::destroy_at(&gvl);
    std::construct_at(&gvl);
    CHECK(gvl.udiStarts == 0U);
    CHECK(detail::restore_retained(objects, kept_over(retain_event::cold_reset), std::span(image_buffer).first(size)) ==
          retain_kinds::persistent);
    CHECK(gvl.udiStarts == 0U);
    CHECK(gvl.ltTotal == "LTIME#5s"_iec);
    CHECK(detail::restore_retained(objects, retain_kinds::both, std::span(image_buffer).first(size)) ==
          retain_kinds::both);
    CHECK(gvl.udiStarts == starts);
  }

  TEST_CASE("variables constructed out of address order are saved in address order") {
    struct Slots {
      alignas(retain<INT>) std::byte first[sizeof(retain<INT>)];
      alignas(retain<DINT>) std::byte second[sizeof(retain<DINT>)];
    };
    Slots slots;
    auto* first = reinterpret_cast<retain<INT>*>(slots.first);
    auto* second = reinterpret_cast<retain<DINT>*>(slots.second);
    std::construct_at(second, DINT(200000));
    std::construct_at(first, INT(100));
    const retained_object objects[] = {object_of(slots)};
    const std::size_t size = detail::save_retained(objects, retain_kinds::retain, image_buffer);
    REQUIRE(size == 16 + 16 + 2 + 4);
    INT saved_first;
    std::memcpy(&saved_first, image_buffer.data() + 32, sizeof saved_first);
    CHECK(saved_first == 100);  // the lower address first

    std::destroy_at(first);
    std::destroy_at(second);
    std::construct_at(first);  // now in address order
    std::construct_at(second);
    CHECK(detail::restore_retained(objects, retain_kinds::retain, std::span(image_buffer).first(size)) ==
          retain_kinds::retain);
    CHECK(*first == 100);
    CHECK(*second == 200000);
    std::destroy_at(first);
    std::destroy_at(second);
  }

  TEST_CASE("an online change keeps the values and the new instance's variables are the listed ones") {
    const std::size_t before = listed_variables();
    alignas(FB_Axis) std::byte storage_a[sizeof(FB_Axis)];
    alignas(FB_Axis) std::byte storage_b[sizeof(FB_Axis)];
    FB_Axis& old_axis = first_start<FB_Axis>(storage_a);
    old_axis.lrPosition = 3.5;
    FB_Axis& new_axis = online_change(old_axis, storage_b);
    CHECK(new_axis.lrPosition == 3.5);
    CHECK(listed_variables() == before + 2);
    const retained_object objects[] = {object_of(new_axis)};
    CHECK(detail::retained_count(objects, retain_kinds::both) == 2);
    std::destroy_at(&new_axis);
    CHECK(listed_variables() == before);
  }

  TEST_CASE("a buffer too small is a fault, and nothing is written") {
    iecoop_test::fault_recorder faults;
    PRG_Machine machine;
    const retained_object objects[] = {object_of(machine)};
    const std::size_t needed = detail::retained_image_size(objects, retain_kinds::both);
    std::array<std::byte, 64> small{};
    REQUIRE(needed > small.size());
    CHECK(detail::save_retained(objects, retain_kinds::both, small) == 0);
    CHECK(faults.count == 1);
    CHECK(faults.last_kind == fault_kind::invalid_value);
    CHECK(faults.last_message.find("retained_image_size") != std::string::npos);
    for (const std::byte b : small) CHECK(b == std::byte{0});
    CHECK(detail::save_retained(objects, retain_kinds::both, std::span(image_buffer).first(needed)) == needed);
    CHECK(faults.count == 1);
  }

  TEST_CASE("an image that is not intact restores nothing") {
    PRG_Machine machine;
    change_everything(machine);
    const retained_object objects[] = {object_of(machine)};
    const std::size_t size = detail::save_retained(objects, retain_kinds::both, image_buffer);
    std::array<std::byte, 512> good{};
    std::memcpy(good.data(), image_buffer.data(), size);
    std::destroy_at(&machine);
    std::construct_at(&machine);

    auto restore_damaged = [&](std::size_t at, std::byte value, std::size_t length) {
      std::array<std::byte, 512> damaged = good;
      damaged[at] = value;
      return detail::restore_retained(objects, retain_kinds::both, std::span(damaged).first(length));
    };
    CHECK(restore_damaged(0, std::byte{'X'}, size) == retain_kinds::none);   // magic
    CHECK(restore_damaged(4, std::byte{2}, size) == retain_kinds::none);     // version 2
    CHECK(restore_damaged(8, std::byte{0xFF}, size) == retain_kinds::none);  // total size beyond the data
    CHECK(restore_damaged(8, std::byte{8}, size) == retain_kinds::none);     // total size below the header
    CHECK(restore_damaged(6, std::byte{3}, size) == retain_kinds::none);     // section count
    CHECK(restore_damaged(size - 1, good[size - 1] ^ std::byte{1}, size) == retain_kinds::none);  // a value (checksum)
    CHECK(restore_damaged(16, std::byte{7}, size) == retain_kinds::none);                         // section kind
    CHECK(restore_damaged(0, good[0], size - 1) == retain_kinds::none);                           // truncated
    CHECK(restore_damaged(0, good[0], 10) == retain_kinds::none);  // shorter than a header
    CHECK(detail::restore_retained(objects, retain_kinds::both, {}) == retain_kinds::none);
    check_retain_initial(machine);
    check_persistent_initial(machine);

    // A section header that lies about its data, with a checksum to match: still refused.
    std::array<std::byte, 512> lying = good;
    lying[16 + 12] = std::byte{0xFF};
    detail::retained_put(lying.data() + 12, detail::retained_checksum(std::span(lying).subspan(16, size - 16)), 4);
    CHECK(detail::restore_retained(objects, retain_kinds::both, std::span(lying).first(size)) == retain_kinds::none);

    // Bytes after a complete image: not what a save wrote, damaged like bytes missing
    // (docs/retain.md, "An image is exactly what a save wrote").
    CHECK(detail::restore_retained(objects, retain_kinds::both, std::span(good).first(size + 8)) == retain_kinds::none);
    CHECK(detail::restore_retained(objects, retain_kinds::both, std::span(good).first(size + 1)) == retain_kinds::none);
    check_retain_initial(machine);
    // The image alone restores.
    CHECK(detail::restore_retained(objects, retain_kinds::both, std::span(good).first(size)) == retain_kinds::both);
    check_retain_kept(machine);
  }

  TEST_CASE("memory_storage keeps one image") {
    memory_storage<8> storage;
    std::array<std::byte, 8> buffer{};
    CHECK(storage.load(buffer) == 0);  // nothing saved yet
    const std::array<std::byte, 5> data{std::byte{1}, std::byte{2}, std::byte{3}, std::byte{4}, std::byte{5}};
    CHECK(storage.save(data));
    CHECK(storage.size() == 5);
    CHECK(storage.load(buffer) == 5);
    CHECK(buffer[4] == std::byte{5});
    std::array<std::byte, 4> small{};
    CHECK(storage.load(small) == 0);
    const std::array<std::byte, 9> too_big{};
    CHECK(!storage.save(too_big));
    CHECK(storage.size() == 5);  // unchanged
    storage.clear();
    CHECK(storage.load(buffer) == 0);
    static_assert(memory_storage<8>::capacity() == 8);
  }

  TEST_CASE("memory_storage keeps the image before the last save and one set aside") {
    static_assert(RetainStorageWithPrevious<memory_storage<8>>);
    static_assert(RetainStorageSetAside<memory_storage<8>>);
    memory_storage<8> storage;
    std::array<std::byte, 8> buffer{};
    const auto save = [&](int first, std::size_t size) {  // bytes first, first + 1, ...
      std::array<std::byte, 8> bytes{};
      for (std::size_t i = 0; i < size; ++i) bytes[i] = static_cast<std::byte>(first + static_cast<int>(i));
      return storage.save(std::span(bytes).first(size));
    };
    const auto first_byte = [](std::span<const std::byte> bytes) {
      return bytes.empty() ? -1 : std::to_integer<int>(bytes[0]);
    };
    CHECK(storage.load_previous(buffer) == 0);
    CHECK(save(10, 3));
    CHECK(storage.load_previous(buffer) == 0);  // nothing before the first
    CHECK(save(20, 5));
    CHECK(storage.load(buffer) == 5);
    CHECK(buffer[0] == std::byte{20});
    CHECK(storage.load_previous(buffer) == 3);
    CHECK(buffer[0] == std::byte{10});
    std::array<std::byte, 2> small{};
    CHECK(storage.load_previous(small) == 0);
    CHECK(!storage.save(std::array<std::byte, 9>{}));  // too big: nothing changes
    CHECK(first_byte(storage.previous()) == 10);

    // set_aside: the current image goes aside, the previous one stays, also over the next save.
    CHECK(storage.set_aside());
    CHECK(storage.load(buffer) == 0);
    CHECK(storage.size() == 0);
    CHECK(first_byte(storage.rejected()) == 20);
    CHECK(storage.load_previous(buffer) == 3);
    CHECK(save(30, 4));
    CHECK(first_byte(storage.data()) == 30);
    CHECK(first_byte(storage.previous()) == 10);
    CHECK(first_byte(storage.rejected()) == 20);
    // All three slots are taken now; a save overwrites the previous image's, never the others.
    CHECK(save(40, 8));
    CHECK(first_byte(storage.data()) == 40);
    CHECK(first_byte(storage.previous()) == 30);
    CHECK(first_byte(storage.rejected()) == 20);
    CHECK(save(50, 1));
    CHECK(first_byte(storage.data()) == 50);
    CHECK(first_byte(storage.previous()) == 40);
    CHECK(first_byte(storage.rejected()) == 20);
    CHECK(storage.previous().size() == 8);
    // A second set_aside replaces the image set aside; one without an image changes nothing.
    CHECK(storage.set_aside());
    CHECK(first_byte(storage.rejected()) == 50);
    CHECK(storage.set_aside());
    CHECK(first_byte(storage.rejected()) == 50);
    CHECK(first_byte(storage.previous()) == 40);
    storage.clear();
    CHECK(storage.load_previous(buffer) == 0);
    CHECK(storage.rejected().empty());
  }
}
