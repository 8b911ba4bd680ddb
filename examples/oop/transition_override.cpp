// Seed: "Object 'Transition'" / EXTENDS — "When you insert a transition below a derived POU, you can
// take over (override) a transition of the base POU": a transition object is a member of the POU
// written in SFC, and a derived POU overrides it as it overrides a method, an action or a property.
//
// The seed gives no chart. We complete it minimally: FB_Station is a station written in SFC,
// IDLE -> FILL -> DONE -> IDLE; it fills (the valve open) until its transition object T_Filled
// says the tank is full (level >= 80). FB_FastStation EXTENDS FB_Station and takes over T_Filled:
// it leaves FILL at level 50 already, or after 2 s in FILL whatever the level. The chart is
// FB_Station's: FB_FastStation inherits it and runs it through SUPER^(), and the chart calls
// T_Filled virtually, so the same chart fires on the derived block's condition.
//
// C++: the transition object is a virtual member function returning BOOL, named in the chart as
// &FB_Station::T_Filled; the derived block overrides it (docs/sfc.md, "Transitions").
#include <iecoop/testing.hpp>

namespace seed_transition_override {

using namespace iecoop;
using namespace iecoop::literals;

// FUNCTION_BLOCK FB_Station                         (implementation language: SFC)
struct FB_Station : function_block<FB_Station> {
  virtual ~FB_Station() = default;
  // VAR_INPUT
  BOOL bStart;   // bStart : BOOL;
  INT iLevel;    // iLevel : INT;
  // END_VAR
  // VAR_OUTPUT
  BOOL bValve;   // bValve : BOOL;       (a variable as action of FILL)
  BOOL bDone;    // bDone : BOOL;        (a variable as action of DONE)
  // END_VAR
  using VAR_INPUT = pins<&FB_Station::bStart, &FB_Station::iLevel>;
  using VAR_OUTPUT = pins<&FB_Station::bValve, &FB_Station::bDone>;

  sfc::step IDLE, FILL, DONE;  // the steps' implicit variables (FILL.X, FILL.T)

  // TRANSITION T_Filled                             (a Transition object below FB_Station)
  virtual BOOL T_Filled() {
    return iLevel >= 80;  // T_Filled := iLevel >= 80;
  }
  // END_TRANSITION

  using P = FB_Station;
  sfc::chart<P,
      sfc::INITIAL_STEP<&P::IDLE>,                                          // INITIAL_STEP IDLE: END_STEP
      sfc::TRANSITION<sfc::FROM<&P::IDLE>, sfc::TO<&P::FILL>, &P::bStart>,  // TRANSITION FROM IDLE TO FILL := bStart; END_TRANSITION
      sfc::STEP<&P::FILL, sfc::N<&P::bValve>>,                              // STEP FILL: bValve(N); END_STEP
      sfc::TRANSITION<sfc::FROM<&P::FILL>, sfc::TO<&P::DONE>, &P::T_Filled>,  // TRANSITION FROM FILL TO DONE := T_Filled; END_TRANSITION
      sfc::STEP<&P::DONE, sfc::N<&P::bDone>>,                               // STEP DONE: bDone(N); END_STEP
      sfc::TRANSITION<sfc::FROM<&P::DONE>, sfc::TO<&P::IDLE>,               // TRANSITION FROM DONE TO IDLE := NOT bStart;
                      [](auto& p) { return !p.bStart; }>>                   // END_TRANSITION
      chart;

  virtual void body() { chart(*this); }  // the SFC body
};

// FUNCTION_BLOCK FB_FastStation EXTENDS FB_Station  (implementation language: SFC, the base's chart)
struct FB_FastStation : extends<FB_FastStation, FB_Station> {
  void body() override { SUPER::body(); }  // SUPER^();     the base's chart

  // TRANSITION T_Filled                             (inserted below FB_FastStation: takes over the base's)
  BOOL T_Filled() override {
    return iLevel >= 50 || FILL.T >= "T#2s"_iec;  // T_Filled := iLevel >= 50 OR FILL.T >= T#2s;
  }
  // END_TRANSITION
};

}  // namespace seed_transition_override

using namespace iecoop;
using seed_transition_override::FB_FastStation;
using seed_transition_override::FB_Station;

namespace {
// One 10 ms cycle of a station: the clock advances, then the block is called (through a
// reference to the base, as a caller that only knows FB_Station would).
void cycle(FB_Station& station, BOOL start, INT level) {
  cycle_clock::advance(std::chrono::milliseconds(10));
  station("bStart"_ = start, "iLevel"_ = level);
}
}  // namespace

TEST_SUITE("seed: a derived POU takes over a transition of its base (EXTENDS, Transition object)") {
  TEST_CASE("the base leaves FILL on its own transition: level >= 80") {
    cycle_clock::set(LTIME());
    FB_Station station;
    cycle(station, TRUE, 0);  // IDLE -> FILL fires (codesys order: FILL active next cycle)
    cycle(station, TRUE, 0);
    CHECK(station.FILL.X);
    CHECK(station.bValve);
    cycle(station, TRUE, 60);  // 60 is not full for the base
    cycle(station, TRUE, 79);
    CHECK(station.FILL.X);
    cycle(station, TRUE, 80);  // T_Filled: FILL -> DONE
    cycle(station, TRUE, 80);
    CHECK(station.DONE.X);
    CHECK(station.bDone);
    CHECK_FALSE(station.bValve);
  }

  TEST_CASE("the derived block leaves FILL on its override: level >= 50") {
    cycle_clock::set(LTIME());
    FB_FastStation station;
    cycle(station, TRUE, 0);
    cycle(station, TRUE, 0);
    CHECK(station.FILL.X);
    cycle(station, TRUE, 49);
    CHECK(station.FILL.X);
    cycle(station, TRUE, 50);  // the override fires where the base's would not
    cycle(station, TRUE, 50);
    CHECK(station.DONE.X);
    CHECK(station.bDone);
    cycle(station, FALSE, 50);  // DONE -> IDLE
    cycle(station, FALSE, 50);
    CHECK(station.IDLE.X);
  }

  TEST_CASE("the derived block's timeout: FILL is left after 2 s whatever the level") {
    cycle_clock::set(LTIME());
    FB_FastStation fast;
    FB_Station& station = fast;  // through a reference to the base
    cycle(station, TRUE, 0);
    for (int i = 0; i < 200; ++i) cycle(station, TRUE, 10);  // FILL active for 200 cycles: T#0ms .. T#1990ms
    CHECK(fast.FILL.T == "T#1990ms"_iec);
    CHECK(station.FILL.X);
    cycle(station, TRUE, 10);  // FILL.T = T#2s: the override fires
    CHECK(station.chart.SFCTrans);
    cycle(station, TRUE, 10);
    CHECK(station.DONE.X);
    CHECK(fast.FILL.T == "T#2s"_iec);  // T keeps its value once FILL is left
  }

  TEST_CASE("through a reference to the base, each block uses its own transition") {
    cycle_clock::set(LTIME());
    FB_Station base;
    FB_FastStation fast;
    FB_Station* stations[] = {&base, &fast};
    for (FB_Station* s : stations) cycle(*s, TRUE, 0);
    for (FB_Station* s : stations) cycle(*s, TRUE, 60);  // 60: full for FB_FastStation only
    for (FB_Station* s : stations) cycle(*s, TRUE, 60);
    CHECK(base.FILL.X);
    CHECK(base.bValve);
    CHECK(fast.DONE.X);
    CHECK_FALSE(fast.bValve);
    FB_Station& as_base = fast;
    CHECK(as_base.T_Filled());          // the override, called virtually
    CHECK_FALSE(fast.FB_Station::T_Filled());  // SUPER^'s transition: 60 < 80
  }
}
