// Seed: CODESYS "Object 'Method'" — the special methods of a function block: FB_Init
// (initialisation code; with user parameters supplied where the instance is declared),
// FB_Reinit (after an instance was copied, as during an online change) and FB_Exit (before
// a new download, a reset, or when an instance moves during an online change).
//
// The seed names the methods without code. This port is their usual use: FB_Cylinder gets
// its valve as an FB_Init parameter (dependency injection) and FB_Exit closes the valve.
// FB_LiftCylinder EXTENDS FB_Cylinder with an FB_Init of its own. Every lifecycle call is
// written to a log, so the tests check CODESYS's order and flags for the first start,
// resets and an online change.
#include <doctest/doctest.h>

#include <iecoop/iecoop.hpp>
#include <iecoop/ostream.hpp>

#include <memory>
#include <utility>

namespace seed_fb_init {

using namespace iecoop;

// VAR_GLOBAL  gLog : STRING(255); END_VAR
inline STRING<255> gLog;

inline STRING<5> Flag(BOOL b) { return b ? "TRUE" : "FALSE"; }

// FUNCTION_BLOCK FB_Valve
struct FB_Valve : function_block<FB_Valve> {
  BOOL bOpen;    // VAR_INPUT
  BOOL bIsOpen;  // VAR_OUTPUT
  using VAR_INPUT = pins<&FB_Valve::bOpen>;
  using VAR_OUTPUT = pins<&FB_Valve::bIsOpen>;
  void body() { bIsOpen = bOpen; }
};

// FUNCTION_BLOCK FB_Cylinder
struct FB_Cylinder : function_block<FB_Cylinder> {
  // The declaration supplies FB_Init's parameters, then optional initial values:
  //   cylinder : FB_Cylinder(valve := mainValve, nId := 1) := (tMax := T#3s);
  template <NamedInput... Initial>
  explicit FB_Cylinder(FB_Valve& valve, INT id, Initial&&... initial) {
    run_fb_init(*this, valve, id, std::forward<Initial>(initial)...);
  }
  virtual ~FB_Cylinder() { run_fb_exit(*this); }
  FB_Cylinder(const FB_Cylinder&) = default;  // an online change copies instances
  FB_Cylinder& operator=(const FB_Cylinder&) = default;

  // VAR_INPUT  bExtend : BOOL; tMax : TIME := T#2s; END_VAR
  BOOL bExtend;
  TIME tMax = "T#2s"_iec;
  // VAR_OUTPUT bExtended : BOOL; END_VAR
  BOOL bExtended;
  // VAR        pValve : POINTER TO FB_Valve; nId : INT; nReinits : INT; END_VAR
  FB_Valve* pValve = nullptr;
  INT nId;
  INT nReinits;

  using VAR_INPUT = pins<&FB_Cylinder::bExtend, &FB_Cylinder::tMax>;
  using VAR_OUTPUT = pins<&FB_Cylinder::bExtended>;

  // METHOD FB_Init : BOOL
  // VAR_INPUT bInitRetains : BOOL; bInCopyCode : BOOL; valve : REFERENCE TO FB_Valve; nId : INT; END_VAR
  BOOL FB_Init(BOOL bInitRetains, BOOL bInCopyCode, FB_Valve& valve, INT id) {
    pValve = &valve;    // pValve := ADR(valve);
    nId = id;           // THIS^.nId := nId;
    tMax = "T#5s"_iec;  // tMax := T#5s;   (an initial value in the declaration overwrites this)
    gLog = CONCAT(gLog, "Cylinder.Init(", Flag(bInitRetains), ",", Flag(bInCopyCode), ") ");
    return TRUE;
  }
  // METHOD FB_Reinit : BOOL
  BOOL FB_Reinit() {
    nReinits = nReinits + 1;
    gLog = CONCAT(gLog, "Cylinder.Reinit ");
    return TRUE;
  }
  // METHOD FB_Exit : BOOL
  // VAR_INPUT bInCopyCode : BOOL; END_VAR
  BOOL FB_Exit(BOOL bInCopyCode) {
    if (!bInCopyCode) pValve->bOpen = FALSE;  // IF NOT bInCopyCode THEN pValve^.bOpen := FALSE; END_IF
    gLog = CONCAT(gLog, "Cylinder.Exit(", Flag(bInCopyCode), ") ");
    return TRUE;
  }

  virtual void body() {
    (*pValve)("bOpen"_ = bExtend);  // pValve^(bOpen := bExtend);
    bExtended = pValve->bIsOpen;    // bExtended := pValve^.bIsOpen;
  }
};

// FUNCTION_BLOCK FB_LiftCylinder EXTENDS FB_Cylinder
struct FB_LiftCylinder : extends<FB_LiftCylinder, FB_Cylinder> {
  // Its FB_Init repeats the base's parameters and adds rLoad (a CODESYS rule).
  template <NamedInput... Initial>
  FB_LiftCylinder(FB_Valve& valve, INT id, REAL load, Initial&&... initial) : extends(valve, id) {
    run_fb_init(*this, valve, id, load, std::forward<Initial>(initial)...);
  }
  ~FB_LiftCylinder() override { run_fb_exit(*this); }
  void body() override { SUPER::body(); }  // SUPER^();  (the cylinder's own code)
  FB_LiftCylinder(const FB_LiftCylinder&) = default;
  FB_LiftCylinder& operator=(const FB_LiftCylinder&) = default;

  // VAR rLoad : REAL; END_VAR
  REAL rLoad;

  // METHOD FB_Init : BOOL
  // VAR_INPUT bInitRetains : BOOL; bInCopyCode : BOOL; valve : REFERENCE TO FB_Valve; nId : INT; rLoad : REAL; END_VAR
  BOOL FB_Init(BOOL bInitRetains, BOOL bInCopyCode, FB_Valve&, INT, REAL load) {
    rLoad = load;
    gLog = CONCAT(gLog, "Lift.Init(", Flag(bInitRetains), ",", Flag(bInCopyCode), ") ");
    return TRUE;
  }
  // METHOD FB_Reinit : BOOL           (the base's FB_Reinit is not called automatically)
  BOOL FB_Reinit() {
    SUPER::FB_Reinit();  // SUPER^.FB_Reinit();
    gLog = CONCAT(gLog, "Lift.Reinit ");
    return TRUE;
  }
  // METHOD FB_Exit : BOOL
  BOOL FB_Exit(BOOL bInCopyCode) {
    gLog = CONCAT(gLog, "Lift.Exit(", Flag(bInCopyCode), ") ");
    return TRUE;
  }
};

// PROGRAM PLC_PRG
struct PLC_PRG : program<PLC_PRG> {
  // VAR mainValve : FB_Valve; cylinder : FB_Cylinder(valve := mainValve, nId := 1); END_VAR
  FB_Valve mainValve;
  FB_Cylinder cylinder{mainValve, 1};
  // VAR bCommand : BOOL; END_VAR
  BOOL bCommand;
  using VAR_INPUT = pins<&PLC_PRG::bCommand>;

  void body() { cylinder("bExtend"_ = bCommand); }
};

}  // namespace seed_fb_init

using namespace iecoop;
using namespace seed_fb_init;

TEST_SUITE("seed: FB_Init, FB_Reinit, FB_Exit") {
  TEST_CASE("the declaration supplies FB_Init's parameter, first start passes TRUE, FALSE") {
    gLog = "";
    FB_Valve valve;
    {
      FB_Cylinder cylinder{valve, 7};  // cylinder : FB_Cylinder(valve := valve, nId := 7);
      CHECK(gLog == "Cylinder.Init(TRUE,FALSE) ");
      CHECK(cylinder.pValve == &valve);
      CHECK(cylinder.nId == 7);
      CHECK(cylinder.tMax == "T#5s"_iec);  // FB_Init ran after the declared initial value T#2s
      cylinder("bExtend"_ = TRUE);
      CHECK(valve.bIsOpen == TRUE);
      CHECK(cylinder.bExtended == TRUE);
    }
    // Leaving the scope is the end of the instance: FB_Exit(FALSE) closed the valve.
    CHECK(gLog == "Cylinder.Init(TRUE,FALSE) Cylinder.Exit(FALSE) ");
    CHECK(valve.bOpen == FALSE);
  }

  TEST_CASE("initial values in the declaration overwrite what FB_Init wrote") {
    FB_Valve valve;
    FB_Cylinder cylinder{valve, 1, "tMax"_ = "T#3s"_iec};  // ... := (tMax := T#3s);
    CHECK(cylinder.tMax == "T#3s"_iec);
  }

  TEST_CASE("a derived block: base FB_Init first, FB_Exit derived first") {
    FB_Valve valve;
    gLog = "";
    {
      FB_LiftCylinder lift{valve, 2, 1.5f};
      CHECK(gLog == "Cylinder.Init(TRUE,FALSE) Lift.Init(TRUE,FALSE) ");
      CHECK(lift.rLoad == 1.5f);
      CHECK(lift.nId == 2);
      gLog = "";
    }
    CHECK(gLog == "Lift.Exit(FALSE) Cylinder.Exit(FALSE) ");
  }

  TEST_CASE("reset warm and cold: FB_Exit(FALSE), then FB_Init with bInitRetains FALSE or TRUE") {
    FB_Valve valve;
    FB_Cylinder cylinder{valve, 3};
    cylinder.nReinits = 5;
    gLog = "";
    reset(cylinder, reset_kind::warm, valve, INT(3));
    CHECK(gLog == "Cylinder.Exit(FALSE) Cylinder.Init(FALSE,FALSE) ");
    CHECK(cylinder.nReinits == 0);  // everything else starts again from its initial value
    gLog = "";
    reset(cylinder, reset_kind::cold, valve, INT(3));
    CHECK(gLog == "Cylinder.Exit(FALSE) Cylinder.Init(TRUE,FALSE) ");
    gLog = "";
    reset(cylinder, reset_kind::origin, valve, INT(3));
    CHECK(gLog == "Cylinder.Exit(FALSE) Cylinder.Init(TRUE,FALSE) ");
  }

  TEST_CASE("online change: FB_Exit(TRUE), FB_Init(FALSE, TRUE), copy, FB_Reinit") {
    FB_Valve valve;
    alignas(FB_LiftCylinder) unsigned char old_storage[sizeof(FB_LiftCylinder)];
    alignas(FB_LiftCylinder) unsigned char new_storage[sizeof(FB_LiftCylinder)];
    auto& old_lift = first_start<FB_LiftCylinder>(old_storage, valve, INT(4), REAL(2.0f));
    old_lift("bExtend"_ = TRUE);
    old_lift.nReinits = 1;
    gLog = "";
    FB_LiftCylinder& moved = online_change(old_lift, new_storage, valve, INT(4), REAL(0.0f));
    CHECK(gLog ==
          "Lift.Exit(TRUE) Cylinder.Exit(TRUE) Cylinder.Init(FALSE,TRUE) Lift.Init(FALSE,TRUE) Cylinder.Reinit Lift.Reinit ");
    CHECK(static_cast<void*>(&moved) == static_cast<void*>(new_storage));
    CHECK(moved.bExtend == TRUE);  // the old instance's data, copied over
    CHECK(moved.rLoad == 2.0f);    // copied over what FB_Init wrote
    CHECK(moved.nReinits == 2);    // FB_Reinit ran after the copy
    CHECK(valve.bOpen == TRUE);    // FB_Exit(TRUE) left the valve alone
    gLog = "";
    std::destroy_at(&moved);
    CHECK(gLog == "Lift.Exit(FALSE) Cylinder.Exit(FALSE) ");
  }

  TEST_CASE("resetting a program re-initialises every instance declared in it") {
    PLC_PRG plc_prg;
    plc_prg("bCommand"_ = TRUE);
    CHECK(plc_prg.mainValve.bIsOpen == TRUE);
    gLog = "";
    reset(plc_prg, reset_kind::cold);
    CHECK(gLog == "Cylinder.Exit(FALSE) Cylinder.Init(TRUE,FALSE) ");
    CHECK(plc_prg.cylinder.pValve == &plc_prg.mainValve);
    CHECK(plc_prg.mainValve.bIsOpen == FALSE);
    CHECK(&PLC_PRG::instance() == &plc_prg);
  }
}
