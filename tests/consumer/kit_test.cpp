// A consumer's unit tests written with the installed test kit (iecoop::testing_main,
// iecoop_discover_tests): a block alone, an application as a fixture, a timing diagram, an
// expected fault.
#include <iecoop/testing.hpp>

using namespace iecoop;

namespace {

// FUNCTION_BLOCK FB_Valve: opens on bOpen; bTimeout after tMax open without bAtLevel.
struct FB_Valve : function_block<FB_Valve> {
  BOOL bOpen;
  BOOL bAtLevel;
  TIME tMax = "T#5s"_iec;
  BOOL qxValve;
  BOOL bTimeout;
  TON tOpen;
  using VAR_INPUT = pins<&FB_Valve::bOpen, &FB_Valve::bAtLevel, &FB_Valve::tMax>;
  using VAR_OUTPUT = pins<&FB_Valve::qxValve, &FB_Valve::bTimeout>;
  void body() {
    tOpen("IN"_ = bOpen & !bAtLevel, "PT"_ = tMax);  // tOpen(IN := bOpen AND NOT bAtLevel, PT := tMax);
    bTimeout = bTimeout | tOpen.Q;                   // bTimeout := bTimeout OR tOpen.Q;
    qxValve = bOpen & !bAtLevel & !bTimeout;         // qxValve := bOpen AND NOT bAtLevel AND NOT bTimeout;
  }
};

struct GVL : global_variables<GVL> {
  BOOL bOpen;
  BOOL bAtLevel;
  BOOL bTimeout;
  INT iShare = 1;
};
struct PLC_PRG : program<PLC_PRG> {
  FB_Valve fbValve;
  INT iPerShare;
  void body() {
    GVL& gvl = GVL::instance();
    fbValve("bOpen"_ = gvl.bOpen, "bAtLevel"_ = gvl.bAtLevel);
    gvl.bTimeout = fbValve.bTimeout;
    iPerShare = INT(100) / gvl.iShare;
  }
};
auto make_plc() { return application{task<PLC_PRG>{"Main", cyclic{"T#10ms"_iec}, 0}, globals<GVL>{}}; }

struct ValveTest : testing::plc<make_plc> {
  GVL& gvl = get<GVL>();
  PLC_PRG& prg = get<PLC_PRG>();
};

}  // namespace

TEST_SUITE("FB_Valve") {
  TEST_CASE("times out after tMax") {
    FB_Valve fb;
    testing::cycles run{fb, "T#100ms"_iec};
    fb.bOpen = TRUE;
    run.step();
    CHECK(fb.qxValve);
    REQUIRE(run.run_until(fb.bTimeout, "T#6s"_iec));
    CHECK(run.now() == LTIME(TIME(5100)));
    CHECK_FALSE(fb.qxValve);
  }
  TEST_CASE("as a timing diagram") {
    FB_Valve fb;
    fb.tMax = "T#30ms"_iec;
    testing::cycles run{fb, "T#10ms"_iec};
    CHECK(testing::run_diagram(
        run, testing::drive("bOpen", fb.bOpen, "_#######"), testing::drive("bAtLevel", fb.bAtLevel, "___#____"),
        testing::expect("qxValve", fb.qxValve, "_##_###_"), testing::expect("bTimeout", fb.bTimeout, "_______#")));
  }
}

TEST_SUITE("PLC_PRG") {
  TEST_CASE_FIXTURE(ValveTest, "stops at the level") {
    force(gvl.bOpen, TRUE);
    step();
    CHECK(prg.fbValve.qxValve);
    write(gvl.bAtLevel, TRUE);
    step();
    CHECK_FALSE(prg.fbValve.qxValve);
    CHECK(forced(gvl.bOpen));
  }
  TEST_CASE_FIXTURE(ValveTest, "a share of 0 divides by zero") {
    write(gvl.iShare, INT(0));
    CHECK_FAULT(step(), fault_kind::division_by_zero);
  }
}
