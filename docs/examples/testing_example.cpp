// Generated from docs/testing.md by tools/doc_example.cmake: edit the page, then run
//   cmake -DMARKDOWN=docs/testing.md -DOUTPUT=docs/examples/testing_example.cpp -P tools/doc_example.cmake
// The page's C++ blocks in order, as one program (its ST is in the page). Built with the test
// kit's main(): `-DIECOOP_TESTING_MAIN`, or linked to iecoop::testing_main.
#include <iecoop/testing.hpp>

#include <string_view>

using namespace iecoop;

struct FB_FillValve : function_block<FB_FillValve> {
  // VAR_INPUT
  BOOL bStart;
  BOOL bFull;
  TIME tTimeout = "T#5s"_iec;

  // VAR_OUTPUT
  BOOL bValve;
  BOOL bTimeout;

  // VAR
  R_TRIG rtStart;
  TON tonFill;

  using VAR_INPUT =
      pins<&FB_FillValve::bStart, &FB_FillValve::bFull, &FB_FillValve::tTimeout>;
  using VAR_OUTPUT = pins<&FB_FillValve::bValve, &FB_FillValve::bTimeout>;

  void body() {
    rtStart("CLK"_ = bStart);
    if (rtStart.Q & ~bFull) {
      bValve = TRUE;
      bTimeout = FALSE;
    }
    if (bFull) {
      bValve = FALSE;
    }
    tonFill("IN"_ = bValve, "PT"_ = tTimeout);
    if (tonFill.Q) {
      bValve = FALSE;
      bTimeout = TRUE;
    }
  }
};

TEST_SUITE("FB_FillValve") {
  TEST_CASE("opens on START and closes when full") {
    FB_FillValve fbValve;
    testing::cycles run{fbValve, "T#10ms"_iec};  // fbValve() every 10 ms of simulated time
    fbValve.bStart = TRUE;
    run.step();                                  // one cycle, at T#0ms
    CHECK(fbValve.bValve);
    run.advance("T#2s"_iec);                     // the 200 cycles of the next two seconds
    CHECK(fbValve.bValve);
    fbValve.bFull = TRUE;
    run.step();
    CHECK_FALSE(fbValve.bValve);
    CHECK_FALSE(fbValve.bTimeout);
    CHECK(run.cycle() == 202);                   // cycles run
    CHECK(run.now() == "T#2s20ms"_iec);          // the time of the next cycle
  }

  TEST_CASE("gives up after tTimeout without the level switch") {
    FB_FillValve fbValve;
    fbValve.tTimeout = "T#3s"_iec;
    testing::cycles run{fbValve, "T#10ms"_iec};
    fbValve.bStart = TRUE;
    REQUIRE(run.run_until(fbValve.bTimeout, "T#4s"_iec));  // at most T#4s of cycles
    CHECK_FALSE(fbValve.bValve);
    CHECK(fbValve.tonFill.ET == "T#3s"_iec);
    CHECK(run.now() == "T#3s10ms"_iec);
  }
}

struct GVL_Fill : global_variables<GVL_Fill> {
  [[no_unique_address]] located<BOOL, "%IX0.0"> ixStart;
  [[no_unique_address]] located<BOOL, "%IX0.1"> ixFull;
  [[no_unique_address]] located<BOOL, "%QX0.0"> qxValve;
  [[no_unique_address]] located<BOOL, "%QX0.1"> qxAlarm;
  INT iPerCrate = 6;
  using LOCATED =
      pins<&GVL_Fill::ixStart, &GVL_Fill::ixFull, &GVL_Fill::qxValve, &GVL_Fill::qxAlarm>;
};

struct FILL_PRG : program<FILL_PRG> {
  // VAR
  FB_FillValve fbValve;
  F_TRIG ftValve;
  var<INT> iBottles;
  var<INT> iCrates;

  void body() {
    GVL_Fill& gvl = GVL_Fill::instance();
    fbValve("bStart"_ = gvl.ixStart, "bFull"_ = gvl.ixFull,
            "bValve"_ >> gvl.qxValve, "bTimeout"_ >> gvl.qxAlarm);

    ftValve("CLK"_ = fbValve.bValve);
    if (ftValve.Q & ~fbValve.bTimeout) {
      iBottles = iBottles + 1;
    }
    iCrates = iBottles / gvl.iPerCrate;
  }
};

inline auto make_filler() {
  return application{task<FILL_PRG>{"Fast", cyclic{"T#10ms"_iec}, 0},
                     globals<GVL_Fill>{}};
}

struct FillerTest : testing::plc<make_filler> {
  GVL_Fill& gvl = get<GVL_Fill>();  // the application's instances
  FILL_PRG& prg = get<FILL_PRG>();

  FillerTest() {                   // setup, before each test case
    write(gvl.iPerCrate, INT(4));  // these tests' recipe: crates of 4 (written at the first cycle)
  }
  ~FillerTest() {                  // teardown, after each test case
    if (gvl.qxAlarm) CHECK_FALSE(gvl.qxValve);  // never the valve open with the alarm on
  }
};

TEST_SUITE("FILL_PRG") {
  TEST_CASE_FIXTURE(FillerTest, "fills a bottle and counts it") {
    pulse(gvl.ixStart);          // %IX0.0 TRUE for one cycle, then FALSE again
    CHECK(gvl.qxValve);
    advance("T#3s"_iec);         // the cycles of the next three seconds
    CHECK(gvl.qxValve);
    force(gvl.ixFull, TRUE);     // the level switch, from the next cycle on
    step();
    CHECK_FALSE(gvl.qxValve);
    CHECK(prg.iBottles == 1);
    CHECK(now() == "T#3s20ms"_iec);
  }

  TEST_CASE_FIXTURE(FillerTest, "the alarm lamp after 5 s without the level switch") {
    pulse(gvl.ixStart);
    REQUIRE(run_until(gvl.qxAlarm, "T#6s"_iec));
    CHECK(now() == "T#5s10ms"_iec);
    CHECK_FALSE(gvl.qxValve);
    CHECK(prg.iBottles == 0);
  }
}

TEST_SUITE("FB_FillValve") {
  TEST_CASE("durations are written with their unit") {
    using namespace std::chrono_literals;
    FB_FillValve fbValve;
    fbValve.tTimeout = "T#3s"_iec;
    testing::cycles run{fbValve, 10ms};  // the cycle time: "T#10ms"_iec, or 10ms
    fbValve.bStart = TRUE;
    run.advance("T#1s"_iec);
    run.advance(1s);  // the same
    CHECK_FALSE(fbValve.bTimeout);
    run.advance(fbValve.tTimeout);  // a TIME variable: three seconds more
    CHECK(fbValve.bTimeout);
    // run.advance(3000);           // does not compile: 3000 what?
  }
}

TEST_SUITE("FILL_PRG") {
  TEST_CASE_FIXTURE(FillerTest, "a forced output keeps the valve shut in the field") {
    force(gvl.qxValve, FALSE);   // %QX0.0
    pulse(gvl.ixStart);
    CHECK(prg.fbValve.bValve);   // the program opened it ...
    CHECK_FALSE(gvl.qxValve);    // ... the output is FALSE at the cycle's end
    CHECK(forced(gvl.qxValve));
    release(gvl.qxValve);        // keeps its value until the program writes it
    step();
    CHECK(gvl.qxValve);
  }

  TEST_CASE_FIXTURE(FillerTest, "the input of a block inside the program forced") {
    force(prg.fbValve.tTimeout, "T#1s"_iec);
    pulse(gvl.ixStart);
    REQUIRE(run_until(gvl.qxAlarm, "T#2s"_iec));
    CHECK(now() == "T#1s10ms"_iec);
  }

  TEST_CASE_FIXTURE(FillerTest, "a counter written once") {
    write(prg.iBottles, INT(11));  // at the next cycle's start; the program counts on from there
    pulse(gvl.ixStart);
    force(gvl.ixFull, TRUE);
    step();
    CHECK(prg.iBottles == 12);
    CHECK(prg.iCrates == 3);       // crates of 4: the fixture's recipe
  }
}

TEST_SUITE("FILL_PRG") {
  TEST_CASE_FIXTURE(FillerTest, "a recipe of 0 bottles a crate divides by zero") {
    write(gvl.iPerCrate, INT(0));
    CHECK_FAULT(step(), fault_kind::division_by_zero);  // this fault, and no other

    testing::expect_faults faults;  // the faults of the cycles while it lives
    step(3);
    CHECK(faults.count() == 3);
    CHECK(faults.only(fault_kind::division_by_zero));
    CHECK(faults.last().task == std::string_view("Fast"));
    CHECK(faults.last().pou == std::string_view("FILL_PRG"));
    CHECK(faults.last().time == "T#30ms"_iec);  // the cycle clock: the third of these cycles
  }
}

TEST_SUITE("FB_FillValve") {
  TEST_CASE("timing diagram: two fills") {
    FB_FillValve fbValve;
    testing::cycles run{fbValve, "T#10ms"_iec};
    CHECK(testing::run_diagram(run,                                             //
                               testing::drive("bStart", fbValve.bStart, "_##_____##__"),
                               testing::drive("bFull", fbValve.bFull, "___#________"),
                               testing::expect("bValve", fbValve.bValve, "_##_____####"),
                               testing::expect("bTimeout", fbValve.bTimeout, "____________")));
  }

  TEST_CASE("timing diagram: the timeout and tonFill.ET") {
    FB_FillValve fbValve;
    fbValve.tTimeout = "T#30ms"_iec;
    testing::cycles run{fbValve, "T#10ms"_iec};
    CHECK(testing::run_diagram(run,                                             //
                               testing::drive("bStart", fbValve.bStart, "_#######__"),
                               testing::expect("bValve", fbValve.bValve, "_###......"),
                               testing::expect("bTimeout", fbValve.bTimeout, "____######"),
                               testing::expect("ET", fbValve.tonFill.ET, "0 0 10 20 30 0 0 0 0 0")));
  }
}

TEST_SUITE("FILL_PRG") {
  TEST_CASE_FIXTURE(FillerTest, "timing diagram: two bottles") {
    CHECK(testing::run_diagram(*this,  // the fixture is the driver
                               testing::drive("ixStart", gvl.ixStart, "_##_______##____"),
                               testing::drive("ixFull", gvl.ixFull, "____##________#_"),
                               testing::expect("qxValve", gvl.qxValve, "_###______####__"),
                               testing::expect("iBottles", prg.iBottles, "0 0 0 0 1 1 1 1 1 1 1 1 1 1 2 2")));
  }
}

TEST_SUITE("FB_FillValve") {
  TEST_CASE("a table of cycles") {
    FB_FillValve fbValve;
    testing::cycles run{fbValve};
    CHECK(testing::run_table(run,
                             "cycle,time_ms,bStart,bFull,bValve,bTimeout,ET_ms,note\n"
                             "0,0,0,0,0,0,0,\n"
                             "1,10,1,0,1,0,0,START\n"
                             "2,2000,1,0,1,0,1990,filling\n"
                             "3,2010,1,1,0,0,0,full\n",
                             testing::drive("bStart", fbValve.bStart), testing::drive("bFull", fbValve.bFull),
                             testing::expect("bValve", fbValve.bValve), testing::expect("bTimeout", fbValve.bTimeout),
                             testing::expect("ET", fbValve.tonFill.ET)));
  }
}
