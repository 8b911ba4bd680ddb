// The start-up order of RETAIN and PERSISTENT values and FB_Init (issue 35, point 2): as in
// CODESYS, the kept values are in place when FB_Init runs — FB_Init(bInitRetains := FALSE)
// on a warm start sees them, and what it computes from them stays; on a cold start, a reset
// origin or without stored data FB_Init(bInitRetains := TRUE) sees the initial values. Blocks
// with remanent variables in a program, in a global variable list and nested in another block;
// a named initial value of a RETAIN input; the fallback for variables constructed out of
// address order; a construction that differs from the saved one. See docs/retain.md,
// "Start-up order".
#include "iecoop_test.hpp"

#include <iecoop/runtime/application.hpp>

#include <array>
#include <cstddef>
#include <memory>
#include <span>
#include <string>

using namespace iecoop;
using iecoop_test::fault_recorder;

namespace {

LTIME ms(std::uint64_t n) { return LTIME::from_ticks(n * 1000000U); }

// FUNCTION_BLOCK FB_Starts
//   VAR RETAIN nStarts : UDINT; END_VAR
//   VAR PERSISTENT nTotal : UDINT := 100; END_VAR
//   VAR nSeenStarts, nSeenTotal : UDINT; bSeenInitRetains : BOOL; END_VAR
// METHOD FB_Init : BOOL
//   nSeenStarts := nStarts;  nSeenTotal := nTotal;  bSeenInitRetains := bInitRetains;
//   IF NOT bInitRetains THEN nStarts := nStarts + 1; END_IF   // the warm starts it was kept over
template <int Id>
struct FB_Starts : function_block<FB_Starts<Id>> {
  FB_Starts() { run_fb_init(*this); }
  retain<UDINT> nStarts;
  persistent<UDINT> nTotal{100U};
  UDINT nSeenStarts;
  UDINT nSeenTotal;
  BOOL bSeenInitRetains;
  void body() {}

 private:
  friend struct iecoop::block_access;
  BOOL FB_Init(BOOL bInitRetains, BOOL /*bInCopyCode*/) {
    nSeenStarts = nStarts;
    nSeenTotal = nTotal;
    bSeenInitRetains = bInitRetains;
    if (!bInitRetains) nStarts = nStarts + 1U;
    return TRUE;
  }
};

// FUNCTION_BLOCK FB_Outer: a block with RETAIN nested in another block with RETAIN.
//   VAR inner : FB_Starts; END_VAR  VAR RETAIN iOuter : INT := 5; END_VAR
// METHOD FB_Init: iSeenOuter := iOuter; nSeenInner := inner.nStarts;  (inner's FB_Init ran before)
struct FB_Outer : function_block<FB_Outer> {
  FB_Outer() { run_fb_init(*this); }
  FB_Starts<2> inner;
  retain<INT> iOuter{5};
  INT iSeenOuter;
  UDINT nSeenInner;
  void body() {}

 private:
  friend struct iecoop::block_access;
  BOOL FB_Init(BOOL /*bInitRetains*/, BOOL /*bInCopyCode*/) {
    iSeenOuter = iOuter;
    nSeenInner = inner.nStarts;
    return TRUE;
  }
};

// FUNCTION_BLOCK FB_Setpoint  VAR_INPUT RETAIN iSetpoint : INT; END_VAR
// declared as  fbSet : FB_Setpoint := (iSetpoint := 5);
struct FB_Setpoint : function_block<FB_Setpoint> {
  template <NamedInput... I>
  explicit FB_Setpoint(I&&... initial) {
    run_fb_init(*this, std::forward<I>(initial)...);
  }
  retain<INT> iSetpoint;
  INT iSeen;
  using VAR_INPUT = pins<&FB_Setpoint::iSetpoint>;
  void body() {}

 private:
  friend struct iecoop::block_access;
  BOOL FB_Init(BOOL /*bInitRetains*/, BOOL /*bInCopyCode*/) {
    iSeen = iSetpoint;
    return TRUE;
  }
};

// PROGRAM PRG_Plant
//   VAR fbDirect : FB_Starts; fbOuter : FB_Outer; fbSet : FB_Setpoint := (iSetpoint := 5); END_VAR
//   VAR RETAIN diCount : DINT; END_VAR
struct PRG_Plant : program<PRG_Plant> {
  PRG_Plant() { run_fb_init(*this); }
  FB_Starts<1> fbDirect;
  FB_Outer fbOuter;
  FB_Setpoint fbSet{"iSetpoint"_ = INT(5)};
  retain<DINT> diCount;
  DINT diSeen;
  BOOL bSeenInitRetains;
  void body() { diCount = diCount + 1; }

 private:
  friend struct iecoop::block_access;
  BOOL FB_Init(BOOL bInitRetains, BOOL /*bInCopyCode*/) {
    diSeen = diCount;
    bSeenInitRetains = bInitRetains;
    return TRUE;
  }
};

// VAR_GLOBAL  fbGlobal : FB_Starts; END_VAR
struct GVL_Plant : global_variables<GVL_Plant> {
  FB_Starts<3> fbGlobal;
};

auto make_plant() { return application{task<PRG_Plant>{"Main", cyclic{"T#1ms"_iec}, 1}, globals<GVL_Plant>{}}; }

/// Runs three cycles (diCount 3) and sets every remanent variable to a value of its own.
template <class App>
void run_and_set(App& plc) {
  REQUIRE(plc.start());
  plc.run_for(ms(3));
  PRG_Plant& prg = plc.template get<PRG_Plant>();
  GVL_Plant& gvl = plc.template get<GVL_Plant>();
  prg.fbDirect.nStarts = 7U;
  prg.fbDirect.nTotal = 300U;
  prg.fbOuter.inner.nStarts = 9U;
  prg.fbOuter.iOuter = 50;
  prg.fbSet.iSetpoint = 42;
  gvl.fbGlobal.nStarts = 8U;
  gvl.fbGlobal.nTotal = 400U;
}

/// What FB_Init saw and left after a warm start that kept everything run_and_set set.
template <class App>
void check_warm(App& plc) {
  const PRG_Plant& prg = plc.template get<PRG_Plant>();
  const GVL_Plant& gvl = plc.template get<GVL_Plant>();
  // In a program: FB_Init saw the kept values with bInitRetains FALSE; its +1 stays.
  CHECK(prg.fbDirect.bSeenInitRetains == FALSE);
  CHECK(prg.fbDirect.nSeenStarts == 7U);
  CHECK(prg.fbDirect.nStarts == 8U);
  CHECK(prg.fbDirect.nSeenTotal == 300U);
  CHECK(prg.fbDirect.nTotal == 300U);
  // Nested in a block: the inner block's FB_Init first, then the outer one sees its result.
  CHECK(prg.fbOuter.inner.bSeenInitRetains == FALSE);
  CHECK(prg.fbOuter.inner.nSeenStarts == 9U);
  CHECK(prg.fbOuter.inner.nStarts == 10U);
  CHECK(prg.fbOuter.iSeenOuter == 50);
  CHECK(prg.fbOuter.nSeenInner == 10U);
  // In a global variable list.
  CHECK(gvl.fbGlobal.bSeenInitRetains == FALSE);
  CHECK(gvl.fbGlobal.nSeenStarts == 8U);
  CHECK(gvl.fbGlobal.nStarts == 9U);
  CHECK(gvl.fbGlobal.nSeenTotal == 400U);
  // The program's own variable, and a RETAIN input with a named initial value: kept, not
  // initialised again (bInitRetains FALSE).
  CHECK(prg.bSeenInitRetains == FALSE);
  CHECK(prg.diSeen == 3);
  CHECK(prg.diCount == 3);
  CHECK(prg.fbSet.iSeen == 42);
  CHECK(prg.fbSet.iSetpoint == 42);
  CHECK(plc.retain_status().retain == retain_load::restored);
  CHECK(plc.retain_status().persistent == retain_load::restored);
  CHECK_FALSE(plc.retain_status().restored_after_init);
}

/// After a cold start (cold reset, new download): RETAIN initial, PERSISTENT kept.
template <class App>
void check_cold(App& plc) {
  const PRG_Plant& prg = plc.template get<PRG_Plant>();
  const GVL_Plant& gvl = plc.template get<GVL_Plant>();
  CHECK(prg.fbDirect.bSeenInitRetains == TRUE);
  CHECK(prg.fbDirect.nSeenStarts == 0U);
  CHECK(prg.fbDirect.nStarts == 0U);
  CHECK(prg.fbDirect.nSeenTotal == 300U);  // PERSISTENT: kept, and in place for FB_Init
  CHECK(prg.fbOuter.inner.bSeenInitRetains == TRUE);
  CHECK(prg.fbOuter.inner.nSeenStarts == 0U);
  CHECK(prg.fbOuter.iSeenOuter == 5);
  CHECK(prg.fbOuter.iOuter == 5);
  CHECK(gvl.fbGlobal.bSeenInitRetains == TRUE);
  CHECK(gvl.fbGlobal.nSeenStarts == 0U);
  CHECK(gvl.fbGlobal.nSeenTotal == 400U);
  CHECK(prg.bSeenInitRetains == TRUE);
  CHECK(prg.diSeen == 0);
  CHECK(prg.fbSet.iSeen == 0);      // FB_Init runs before the named initial value...
  CHECK(prg.fbSet.iSetpoint == 5);  // ...which initialises the RETAIN input
  CHECK(plc.retain_status().persistent == retain_load::restored);
}

/// Nothing kept (reset origin, first start): every remanent variable initial in FB_Init.
template <class App>
void check_initial(App& plc) {
  const PRG_Plant& prg = plc.template get<PRG_Plant>();
  const GVL_Plant& gvl = plc.template get<GVL_Plant>();
  CHECK(prg.fbDirect.bSeenInitRetains == TRUE);
  CHECK(prg.fbDirect.nSeenStarts == 0U);
  CHECK(prg.fbDirect.nSeenTotal == 100U);
  CHECK(prg.fbOuter.inner.nSeenTotal == 100U);
  CHECK(prg.fbOuter.iSeenOuter == 5);
  CHECK(gvl.fbGlobal.bSeenInitRetains == TRUE);
  CHECK(gvl.fbGlobal.nSeenTotal == 100U);
  CHECK(prg.bSeenInitRetains == TRUE);
  CHECK(prg.diSeen == 0);
  CHECK(prg.fbSet.iSetpoint == 5);
  CHECK_FALSE(plc.retain_status().BootDataLoaded);
}

}  // namespace

TEST_SUITE("retain: the values are in place before FB_Init") {
  TEST_CASE("warm start (controller restart): FB_Init sees the kept values, bInitRetains FALSE") {
    auto plc = make_plant();
    run_and_set(plc);
    plc.stop();
    REQUIRE(plc.start());
    check_warm(plc);
  }

  TEST_CASE("warm start from the storage, in a new application (another process)") {
    memory_storage<1024> storage;
    {
      auto plc = make_plant();
      plc.use_storage(storage);
      run_and_set(plc);
    }  // stop(): saved
    auto plc = make_plant();
    plc.use_storage(storage);
    REQUIRE(plc.start());
    check_warm(plc);
  }

  TEST_CASE("reset warm: FB_Init sees the kept values, and what it computed stays after the cycles") {
    auto plc = make_plant();
    run_and_set(plc);
    plc.reset(reset_kind::warm);
    check_warm(plc);
    REQUIRE(plc.start());
    plc.run_for(ms(2));
    CHECK(plc.get<PRG_Plant>().fbDirect.nStarts == 8U);
    CHECK(plc.get<PRG_Plant>().diCount == 5);
    plc.reset(reset_kind::warm);  // a second warm start counts on from there
    CHECK(plc.get<PRG_Plant>().fbDirect.nSeenStarts == 8U);
    CHECK(plc.get<PRG_Plant>().fbDirect.nStarts == 9U);
  }

  TEST_CASE("reset cold: FB_Init sees the initial RETAIN values (bInitRetains TRUE) and the kept PERSISTENT ones") {
    auto plc = make_plant();
    run_and_set(plc);
    plc.reset(reset_kind::cold);
    check_cold(plc);
    CHECK(plc.retain_status().retain == retain_load::not_kept);
  }

  TEST_CASE("new download: as a cold start, from the storage") {
    memory_storage<1024> storage;
    {
      auto plc = make_plant();
      plc.use_storage(storage);
      run_and_set(plc);
    }
    auto plc = make_plant();
    plc.use_storage(storage);
    REQUIRE(plc.start(start_mode::download));
    check_cold(plc);
    CHECK(plc.retain_status().retain == retain_load::not_kept);
  }

  TEST_CASE("reset origin: FB_Init sees every initial value, bInitRetains TRUE") {
    auto plc = make_plant();
    run_and_set(plc);
    plc.reset(reset_kind::origin);
    check_initial(plc);
    CHECK(plc.retain_status().retain == retain_load::not_kept);
    CHECK(plc.retain_status().persistent == retain_load::not_kept);
  }

  TEST_CASE("first start, nothing stored: FB_Init sees every initial value, bInitRetains TRUE") {
    memory_storage<1024> storage;
    auto plc = make_plant();
    plc.use_storage(storage);
    REQUIRE(plc.start());
    check_initial(plc);
    CHECK(plc.retain_status().retain == retain_load::initial);
  }
}

// --- Variables constructed out of address order: restored after FB_Init, and said so -------

namespace {

// A program that constructs one RETAIN variable in its constructor, into storage that lies
// before another one (so that construction and address orders differ).
struct PRG_Late : program<PRG_Late> {
  PRG_Late() {
    std::construct_at(first(), INT(1));
    run_fb_init(*this);
  }
  ~PRG_Late() { std::destroy_at(first()); }
  PRG_Late(const PRG_Late&) = delete;
  PRG_Late& operator=(const PRG_Late&) = delete;
  alignas(retain<INT>) std::byte slot[sizeof(retain<INT>)];
  retain<INT> iSecond{2};
  INT iSeenFirst;
  INT iSeenSecond;
  retain<INT>* first() { return std::launder(reinterpret_cast<retain<INT>*>(slot)); }
  void body() {}

 private:
  friend struct iecoop::block_access;
  BOOL FB_Init(BOOL /*bInitRetains*/, BOOL /*bInCopyCode*/) {
    iSeenFirst = *first();
    iSeenSecond = iSecond;
    return TRUE;
  }
};

// A program whose constructor makes a RETAIN variable every other time: its construction
// differs from the one its image was saved from.
struct PRG_Fickle : program<PRG_Fickle> {
  static inline int constructions = 0;
  PRG_Fickle() : made(++constructions % 2 == 1) {
    if (made) std::construct_at(extra(), INT(1));
  }
  ~PRG_Fickle() {
    if (made) std::destroy_at(extra());
  }
  PRG_Fickle(const PRG_Fickle&) = delete;
  PRG_Fickle& operator=(const PRG_Fickle&) = delete;
  retain<INT> iKept{3};
  bool made;
  alignas(retain<INT>) std::byte slot[sizeof(retain<INT>)];
  retain<INT>* extra() { return std::launder(reinterpret_cast<retain<INT>*>(slot)); }
  void body() {}
};

}  // namespace

TEST_SUITE("retain: when the values cannot be in place before FB_Init") {
  TEST_CASE("variables constructed out of address order: restored after FB_Init, restored_after_init") {
    application plc{task<PRG_Late>{"Main", cyclic{"T#1ms"_iec}, 1}};
    REQUIRE(plc.start());
    PRG_Late& prg = plc.get<PRG_Late>();
    *prg.first() = 10;
    prg.iSecond = 20;
    plc.reset(reset_kind::warm);
    CHECK(plc.get<PRG_Late>().iSeenFirst == 1);  // FB_Init saw the initial values...
    CHECK(plc.get<PRG_Late>().iSeenSecond == 2);
    CHECK(*plc.get<PRG_Late>().first() == 10);  // ...the kept ones came back after it
    CHECK(plc.get<PRG_Late>().iSecond == 20);
    CHECK(plc.retain_status().retain == retain_load::restored);
    CHECK(plc.retain_status().restored_after_init);
    plc.reset(reset_kind::cold);
    CHECK_FALSE(plc.retain_status().restored_after_init);  // nothing RETAIN restored
  }

  TEST_CASE("a construction that differs from the saved one: a fault, the instances built again with initial values") {
    fault_recorder faults;
    PRG_Fickle::constructions = 0;
    application plc{task<PRG_Fickle>{"Main", cyclic{"T#1ms"_iec}, 1}};
    REQUIRE(plc.start());  // construction 1: two RETAIN variables
    plc.get<PRG_Fickle>().iKept = 30;
    *plc.get<PRG_Fickle>().extra() = 40;
    plc.reset(reset_kind::warm);  // construction 2 has one: it takes iKept, then ends short of the image
    CHECK(faults.count == 1);
    CHECK(faults.last_kind == fault_kind::invalid_value);
    CHECK(faults.last_message.find("constructed otherwise") != std::string::npos);
    CHECK(PRG_Fickle::constructions == 3);  // built again, without the values
    CHECK(plc.retain_status().retain == retain_load::changed);
    CHECK(plc.get<PRG_Fickle>().iKept == 3);
    CHECK(*plc.get<PRG_Fickle>().extra() == 1);
  }
}

// --- The session on its own, for a runtime of one's own -------------------------------------

namespace {

struct FB_Alone : function_block<FB_Alone> {
  FB_Alone() { run_fb_init(*this); }
  retain<INT> iKept{1};
  persistent<INT> iAlso{2};
  INT iSeen;
  BOOL bSeenInitRetains;
  void body() {}

 private:
  friend struct iecoop::block_access;
  BOOL FB_Init(BOOL bInitRetains, BOOL /*bInCopyCode*/) {
    iSeen = iKept;
    bSeenInitRetains = bInitRetains;
    if (!bInitRetains) iKept = iKept + 1;
    return TRUE;
  }
};

}  // namespace

TEST_CASE("retained_restore_session: a reset in a session of one's own, and a session that found other variables") {
  FB_Alone block;
  block.iKept = 77;
  block.iAlso = 88;
  const detail::retained_object objects[] = {{&block, sizeof block}};
  std::array<std::byte, 256> image{};
  const std::size_t size = detail::save_retained(objects, retain_kinds::both, image);
  const std::span<const std::byte> saved = std::span(image).first(size);
  REQUIRE(detail::retained_in_construction_order(objects, retain_kinds::both) == retain_kinds::both);
  SUBCASE("both kinds") {
    const detail::retained_restore_session restoring(objects, retain_kinds::both, saved);
    reset(block, reset_kind::warm);
    CHECK(restoring.finish() == retain_kinds::both);
    CHECK(block.bSeenInitRetains == FALSE);
    CHECK(block.iSeen == 77);
    CHECK(block.iKept == 78);
    CHECK(block.iAlso == 88);
  }
  SUBCASE("PERSISTENT only (a cold reset)") {
    const detail::retained_restore_session restoring(objects, retain_kinds::persistent, saved);
    reset(block, reset_kind::cold);
    CHECK(restoring.finish() == retain_kinds::persistent);
    CHECK(block.iSeen == 1);
    CHECK(block.iAlso == 88);
  }
  SUBCASE("a section of other variables: the kind fails") {
    struct Other {  // iKept retyped from INT to UINT: same size and offset, another type
      retain<UINT> uRetyped;
      persistent<INT> iAlso;
    } other;
    const detail::retained_object other_objects[] = {{&other, sizeof other}};
    const detail::retained_restore_session restoring(other_objects, retain_kinds::both, saved);
    std::destroy_at(&other);
    std::construct_at(&other);  // the UINT takes the INT's bytes, but the layout hash differs at the end
    CHECK(restoring.finish() == retain_kinds::persistent);  // the RETAIN kind must not be trusted
    CHECK(other.iAlso == 88);
  }
  CHECK((detail::retained_restoring == nullptr));  // the session ended with its scope
  CHECK((detail::kept_at_construction == nullptr));
}
