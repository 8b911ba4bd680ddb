// The test kit's own tests (<iecoop/testing.hpp>, docs/testing.md), written with the kit and
// registered with iecoop_discover_tests, as a user's test program is.
#include <iecoop/testing.hpp>

#include <sstream>
#include <string>

using namespace iecoop;
namespace testing = iecoop::testing;

namespace {

// FUNCTION_BLOCK FB_Div: q := a / b (a fault when b = 0); count := count + 1.
struct FB_Div : function_block<FB_Div> {
  INT a;
  INT b = 1;
  INT q;
  var<INT> count;
  using VAR_INPUT = pins<&FB_Div::a, &FB_Div::b>;
  using VAR_OUTPUT = pins<&FB_Div::q>;
  void body() {
    q = a / b;
    count += 1;
  }
};

// A small application: one program in a 10 ms task, one in a 30 ms task, located I/O.
struct GVL_IO : global_variables<GVL_IO> {
  [[no_unique_address]] located<BOOL, "%IX0.0"> ixButton;
  [[no_unique_address]] located<BOOL, "%QX0.0"> qxLamp;
  [[no_unique_address]] located<WORD, "%QW1"> qwCount;
  using LOCATED = pins<&GVL_IO::ixButton, &GVL_IO::qxLamp, &GVL_IO::qwCount>;
};
struct GVL : global_variables<GVL> {
  INT iDivisor = 1;
  INT iResult;
  WORD wPresses;
};
struct PLC_PRG : program<PLC_PRG> {
  R_TRIG rtButton;
  TON tLamp;
  void body() {
    GVL_IO& io = GVL_IO::instance();
    GVL& gvl = GVL::instance();
    rtButton("CLK"_ = io.ixButton);
    if (rtButton.Q) gvl.wPresses += 1U;
    tLamp("IN"_ = io.ixButton, "PT"_ = "T#50ms"_iec);
    io.qxLamp = tLamp.Q;
    io.qwCount = gvl.wPresses;
  }
};
struct SLOW_PRG : program<SLOW_PRG> {
  void body() {
    GVL& gvl = GVL::instance();
    gvl.iResult = INT(100) / gvl.iDivisor;
  }
};
auto make_plc() {
  return application{task<PLC_PRG>{"Fast", cyclic{"T#10ms"_iec}, 0}, task<SLOW_PRG>{"Slow", cyclic{"T#30ms"_iec}, 5},
                     globals<GVL_IO, GVL>{}};
}

struct PlcTest : testing::plc<make_plc> {
  GVL_IO& io = get<GVL_IO>();
  GVL& gvl = get<GVL>();
};

enum class E_State : std::int16_t { Idle, Run, Fault };

// TYPE ST_Range : STRUCT iLow : INT; tHold : TIME; END_STRUCT END_TYPE (with = for ARRAYs of it)
struct ST_Range {
  INT iLow;
  TIME tHold;
  bool operator==(const ST_Range&) const = default;
};

// A block with an ARRAY variable.
struct FB_Sort : function_block<FB_Sort> {
  var<ARRAY<INT, 1, 3>> aiValues;
  void body() {}
};

template <class T>
std::string printed(const T& value) {
  return doctest::StringMaker<T>::convert(value).c_str();
}

}  // namespace

TEST_SUITE("cycles") {
  TEST_CASE("step sets the cycle clock and moves it by the cycle time") {
    TON tmr;
    testing::cycles run{tmr, "T#10ms"_iec};
    tmr.IN = TRUE;
    tmr.PT = "T#25ms"_iec;
    run.step();
    CHECK(run.now() == LTIME(TIME(10)));
    CHECK(run.cycle() == 1U);
    CHECK(cycle_clock::now() == LTIME{});  // the cycle ran at T#0ms
    run.step(2);
    CHECK(tmr.ET == "T#20ms"_iec);
    CHECK_FALSE(tmr.Q);
    run.advance("T#10ms"_iec);
    CHECK(tmr.Q);
    CHECK(run.cycle() == 4U);
  }

  TEST_CASE("advance rounds up to whole cycles") {
    FB_Div fb;
    testing::cycles run{fb, "T#10ms"_iec};
    run.advance("T#25ms"_iec);
    CHECK(fb.count == 3);
    run.advance(LTIME{});
    CHECK(fb.count == 3);
  }

  TEST_CASE("durations are given with their unit: TIME, LTIME, a variable of one, std::chrono") {
    using namespace std::chrono_literals;
    TON tmr;
    tmr.PT = "T#300ms"_iec;
    tmr.IN = TRUE;
    testing::cycles run{tmr, 100ms};  // std::chrono for the cycle time
    CHECK(run.cycle_time() == LTIME(TIME(100)));
    run.advance(tmr.PT);  // a TIME variable: T#300ms, three cycles
    CHECK(run.cycle() == 3U);
    CHECK_FALSE(tmr.Q);
    run.advance(1s);  // ten cycles, not 1 ns's one
    CHECK(run.cycle() == 13U);
    CHECK(tmr.Q);
    run.advance("LTIME#150ms"_iec);  // rounded up to two cycles
    CHECK(run.cycle() == 15U);
    run.set_cycle_time(std::chrono::milliseconds(50));
    run.set_now(2s);
    run.step();
    CHECK(cycle_clock::now() == LTIME(TIME(2000)));
    CHECK(run.now() == LTIME(TIME(2050)));
    tmr.IN = FALSE;
    run.step();
    tmr.IN = TRUE;
    const testing::wait_result r = run.run_until(tmr.Q, 500ms);  // std::chrono for the timeout
    REQUIRE(r);
    CHECK(r.timeout == LTIME(TIME(500)));
    CHECK(r.waited == LTIME(TIME(350)));  // the edge's cycle, then T#300ms: 7 cycles of T#50ms
  }

  TEST_CASE("a lambda is called as it is, with its arguments") {
    TP pulse;
    BOOL trigger;
    testing::cycles run{[&] { pulse("IN"_ = trigger, "PT"_ = "T#30ms"_iec); }, "T#10ms"_iec, LTIME(TIME(1000))};
    trigger = TRUE;
    run.step();
    CHECK(pulse.Q);
    CHECK(cycle_clock::now() == LTIME(TIME(1000)));
    run.step(3);
    CHECK_FALSE(pulse.Q);
  }

  TEST_CASE("run_until reports when the condition was met") {
    TON tmr;
    tmr.PT = "T#50ms"_iec;
    tmr.IN = TRUE;
    testing::cycles run{tmr, "T#10ms"_iec};
    const testing::wait_result r = run.run_until(tmr.Q, "T#1s"_iec);
    REQUIRE(r);
    CHECK(r.cycles == 6U);  // cycles at 0, 10, ..., 50 ms
    CHECK(r.waited == LTIME(TIME(60)));
    std::ostringstream text;
    text << r;
    CHECK(text.str() == "met after T#60ms (6 cycles)");
  }

  TEST_CASE("run_until stops at the timeout and says where it stopped") {
    TON tmr;
    tmr.PT = "T#1s"_iec;
    tmr.IN = TRUE;
    testing::cycles run{tmr, "T#10ms"_iec};
    const testing::wait_result r = run.run_until([&] { return tmr.Q; }, "T#100ms"_iec);
    CHECK_FALSE(r);
    CHECK(r.cycles == 10U);
    std::ostringstream text;
    text << r;
    CHECK(text.str() == "not met within T#100ms: 10 cycles run, cycle 10, time T#100ms");
  }

  TEST_CASE("a condition met already runs no cycle") {
    FB_Div fb;
    testing::cycles run{fb};
    BOOL yes = TRUE;
    CHECK(run.run_until(yes, "T#1s"_iec).cycles == 0U);
    CHECK(fb.count == 0);
  }

  TEST_CASE("pulse sets a BOOL for n cycles, then gives back its value") {
    R_TRIG edge;
    BOOL clk;
    int rising = 0;
    int high = 0;
    testing::cycles run{[&] {
      edge("CLK"_ = clk);
      rising += edge.Q ? 1 : 0;
      high += clk ? 1 : 0;
    }};
    run.pulse(clk, 3);
    CHECK(high == 3);
    CHECK(rising == 1);
    CHECK_FALSE(clk);
    run.step();
    CHECK(high == 3);
  }

  TEST_CASE("pulse gives a forced BOOL its forced value back, at once") {
    BOOL stop;
    int low = 0;
    testing::cycles run{[&] { low += stop ? 0 : 1; }};
    run.force(stop, TRUE);  // no cycle ran since: the variable is still FALSE
    run.pulse(stop, 2, FALSE);
    CHECK(low == 2);
    CHECK(stop);
    CHECK(run.forced(stop));
    run.step(3);
    CHECK(low == 2);  // forced TRUE again, not FALSE
  }
}

TEST_SUITE("forcing") {
  TEST_CASE("a forced variable wins over the block until released") {
    FB_Div fb;
    testing::cycles run{fb};
    run.force(fb.count, INT(7));  // VAR: the block adds 1 each cycle
    run.force(fb.q, INT(3));      // VAR_OUTPUT
    run.step(2);
    CHECK(fb.count == 7);
    CHECK(fb.q == 3);
    CHECK(run.forced(fb.count));
    CHECK(run.forced_count() == 2U);
    run.release(fb.count);
    CHECK_FALSE(run.forced(fb.count));
    run.step();
    CHECK(fb.count == 8);  // released: the block counts on from the forced value
    run.release_all();
    CHECK(run.forced_count() == 0U);
  }

  TEST_CASE("forcing again replaces the forced value") {
    FB_Div fb;
    testing::cycles run{fb};
    run.force(fb.a, INT(4));
    run.force(fb.a, INT(6));
    run.step();
    CHECK(fb.q == 6);
    CHECK(run.forced_count() == 1U);
  }

  TEST_CASE("a written value is written once") {
    FB_Div fb;
    testing::cycles run{fb};
    run.write(fb.count, INT(100));
    CHECK_FALSE(run.forced(fb.count));
    run.step(2);
    CHECK(fb.count == 102);
  }

  TEST_CASE_FIXTURE(PlcTest, "forcing a located input, output and global variable") {
    force(io.ixButton, TRUE);
    CHECK(forced(io.ixButton));
    advance("T#100ms"_iec);
    CHECK(io.qxLamp);
    CHECK(gvl.wPresses == 1U);
    force(io.qxLamp, FALSE);  // the program writes TRUE; the field sees FALSE
    step();
    CHECK_FALSE(io.qxLamp);
    CHECK((app().published_outputs()[0] & std::byte{1}) == std::byte{0});
    release(io.qxLamp);
    step();
    CHECK(io.qxLamp);
    force(gvl.wPresses, WORD(40));
    step();
    CHECK(io.qwCount == 40U);
  }

  TEST_CASE_FIXTURE(PlcTest, "an address without a variable") {
    force(testing::at<BOOL, "%IX0.0">(), TRUE);
    step(2);
    CHECK(gvl.wPresses == 1U);
    CHECK(forced(testing::at<BOOL, "%IX0.0">()));
    CHECK_FALSE(forced(io.ixButton));  // another variable at the same address is another entry
  }
}

TEST_SUITE("plc") {
  TEST_CASE_FIXTURE(PlcTest, "step runs one base cycle, every task as it is due") {
    CHECK(step_time() == LTIME(TIME(10)));
    step(3);
    CHECK(now() == LTIME(TIME(30)));
    CHECK(task("Fast").statistics().cycles == 3U);
    CHECK(task("Slow").statistics().cycles == 1U);
    CHECK(gvl.iResult == 100);
  }

  TEST_CASE_FIXTURE(PlcTest, "pulse and run_until over an application") {
    pulse(io.ixButton, 2);
    CHECK(gvl.wPresses == 1U);
    pulse(io.ixButton);  // no cycle saw FALSE between the two pulses: no second edge
    CHECK(gvl.wPresses == 1U);
    step();
    pulse(io.ixButton);
    CHECK(gvl.wPresses == 2U);
    step();
    force(io.ixButton, TRUE);
    const testing::wait_result r = run_until(io.qxLamp, "T#1s"_iec);
    REQUIRE(r);
    CHECK(r.cycles == 6U);
  }

  TEST_CASE_FIXTURE(PlcTest, "the application runs for a duration with its unit") {
    using namespace std::chrono_literals;
    app().run_for(90ms);
    CHECK(task("Fast").statistics().cycles == 9U);
    CHECK(task("Slow").statistics().cycles == 3U);
    app().run_until("T#150ms"_iec);  // a time since the start
    CHECK(now() == LTIME(TIME(150)));
    advance(std::chrono::milliseconds(50));
    CHECK(now() == LTIME(TIME(200)));
  }

  TEST_CASE("a fixture's application starts with it and stops after it") {
    {
      testing::plc<make_plc> plc;
      CHECK(plc.app().state() == application_state::running);
      plc.step();
    }
    testing::plc<make_plc> stopped{false};
    CHECK(stopped.app().state() == application_state::stopped);
  }
}

TEST_SUITE("faults") {
  TEST_CASE("CHECK_FAULT expects a fault of one kind") {
    FB_Div fb;
    fb.b = 0;
    testing::cycles run{fb};
    CHECK_FAULT(run.step(), fault_kind::division_by_zero);
    CHECK(fb.q == 0);  // the fault's documented result
    fb.b = 1;
    run.step();
  }

  TEST_CASE("expect_faults records kind, message, task, program and time") {
    testing::plc<make_plc> plc;
    plc.get<GVL>().iDivisor = 0;
    testing::expect_faults faults;
    plc.step(6);
    REQUIRE(faults.count() == 2U);  // Slow runs at 0 and 30 ms
    CHECK(faults.only(fault_kind::division_by_zero));
    CHECK(std::string(faults[1].task) == "Slow");
    CHECK(std::string(faults[1].pou) == "SLOW_PRG");
    CHECK(faults[1].time == LTIME(TIME(30)));
    CHECK(testing::describe(faults[1]) ==
          "division by zero: integer division or MOD by zero; the result is 0 (task Slow, program SLOW_PRG, "
          "cycle clock T#30ms)");
  }

  TEST_CASE("a fault outside a task has no task") {
    testing::expect_faults faults;
    INT zero;
    const INT r = INT(1) / zero;
    CHECK(r == 0);
    REQUIRE(faults.count() == 1U);
    CHECK(faults.last().task == nullptr);
  }

  TEST_CASE("an unexpected fault fails the test case" * doctest::should_fail()) {
    FB_Div fb;
    fb.b = 0;
    testing::cycles run{fb};
    run.step(100);
  }

  TEST_CASE("after an unexpected fault the drivers run no more cycles" * doctest::should_fail()) {
    FB_Div fb;
    fb.b = 0;
    testing::cycles run{fb};
    run.step(100);
    CHECK(testing::faulted());
    CHECK(run.cycle() == 1U);
    CHECK(fb.count == 1);
    CHECK_FALSE(run.run_until([&] { return fb.q == 1; }, "T#1s"_iec).met);
    CHECK(run.cycle() == 1U);
  }

  TEST_CASE("the next case starts without the fault") {
    CHECK_FALSE(testing::faulted());
    FB_Div fb;
    testing::cycles run{fb};
    run.step(3);
    CHECK(run.cycle() == 3U);
  }

  TEST_CASE("a watchdog fault names its task" * doctest::should_fail()) {
    auto make = [] {
      return application{task<PLC_PRG>{"Fast", cyclic{"T#10ms"_iec}, 0, watchdog{"T#5ms"_iec, 1}},
                         globals<GVL_IO, GVL>{}};
    };
    testing::plc<make> plc;
    plc.task("Fast").model_execution_time("T#8ms"_iec);
    plc.step(3);
  }

  // INTERFACE I_Lamp with METHOD Switch; PROGRAM LAMP_PRG calls it through ipLamp, which the
  // test assigns, or not.
  struct I_Lamp : interface_base<I_Lamp> {
    virtual BOOL Switch() = 0;
  };
  struct FB_Lamp : function_block<FB_Lamp, implements<I_Lamp>> {
    BOOL Switch() override { return TRUE; }
  };
  struct LAMP_PRG : program<LAMP_PRG> {
    itf<I_Lamp> ipLamp;
    INT iBefore;
    INT iAfter;
    void body() {
      iBefore += 1;
      ipLamp->Switch();
      iAfter += 1;
    }
  };

  TEST_CASE("a call through an unassigned interface ends the cycle's call, not the test program") {
    FB_Lamp lamp;
    itf<I_Lamp> ip;
    int before = 0;
    int after = 0;
    testing::cycles run{[&] {
      ++before;
      ip->Switch();
      ++after;
    }};
    CHECK_FAULT(run.step(2), fault_kind::unassigned_interface);
    CHECK(before == 2);
    CHECK(after == 0);
    CHECK_FAULT(ip->Switch(), fault_kind::unassigned_interface);
    ip = lamp;
    run.step();
    CHECK(after == 1);
  }

  TEST_CASE("over an application it halts the application, as a PLC stops on an exception") {
    auto make = [] { return application{task<LAMP_PRG>{"Fast", cyclic{"T#10ms"_iec}, 0}}; };
    FB_Lamp lamp;
    testing::plc<make> plc;
    LAMP_PRG& prg = plc.get<LAMP_PRG>();
    testing::expect_faults faults;
    plc.step(3);
    REQUIRE(faults.count() == 1U);
    CHECK(std::string(faults.last().task) == "Fast");
    CHECK(std::string(faults.last().pou) == "LAMP_PRG");
    CHECK(prg.iBefore == 1);
    CHECK(prg.iAfter == 0);
    CHECK(plc.app().state() == application_state::halted);
    CHECK(plc.now() == LTIME(TIME(30)));
    prg.ipLamp = lamp;
    CHECK(plc.app().start());
    plc.step();
    CHECK(prg.iBefore == 2);
    CHECK(prg.iAfter == 1);
  }

  TEST_CASE("an unexpected call through an unassigned interface fails the case, and the run goes on" *
            doctest::should_fail()) {
    testing::cycles run{[] {
      itf<I_Lamp> ip;
      ip->Switch();
    }};
    run.step(5);
    CHECK(run.cycle() == 1U);
  }
}

template <>
inline constexpr auto iecoop::enum_components<E_State> =
    iecoop::components<E_State::Idle, E_State::Run, E_State::Fault>{};

TEST_SUITE("values") {
  TEST_CASE("IEC values print as ST writes them") {
    CHECK(printed(TRUE) == "TRUE");
    CHECK(printed(TIME("T#1s500ms"_iec)) == "T#1s500ms");
    CHECK(printed(WORD(255)) == "16#00FF");
    CHECK(printed(BYTE(10)) == "16#0A");
    CHECK(printed(DWORD(0xDEADBEEFU)) == "16#DEADBEEF");
    CHECK(printed(INT(-5)) == "-5");
    CHECK(printed(STRING<10>("abc")) == "'abc'");
    CHECK(printed(STRING<10>("it's $5")) == "'it$'s $$5'");
    CHECK(printed(WSTRING<10>(u"\u00e9t\u00e9")) == "\"\u00e9t\u00e9\"");
    CHECK(printed(REAL(1.5f)) == "1.5");
    CHECK(printed(E_State::Run) == "Run");
    CHECK(printed(LTIME("LTIME#1ms500us"_iec)) == "LTIME#1ms500us");
    CHECK(printed(DATE("D#2026-11-26"_iec)) == "D#2026-11-26");
    FB_Div fb;
    fb.count = 4;
    CHECK(printed(fb.count) == "4");
    GVL_IO io;
    CHECK(printed(io.qwCount) == "16#0000");
  }
}

TEST_SUITE("diagram") {
  TEST_CASE("a TON as a timing diagram") {
    TON tmr;
    tmr.PT = "T#20ms"_iec;
    testing::cycles run{tmr, "T#10ms"_iec};
    CHECK(testing::run_diagram(run, testing::drive("IN", tmr.IN, "__####____"),
                               testing::expect("Q", tmr.Q, "____##____"),
                               testing::expect("ET", tmr.ET, "0 0 0 10 20 20 0 0 0 0")));
  }

  TEST_CASE("a differing diagram shows both lanes and marks the first difference") {
    TON tmr;
    tmr.PT = "T#20ms"_iec;
    testing::cycles run{tmr, "T#10ms"_iec};
    const testing::diagram_result d = testing::run_diagram(run, testing::drive("IN", tmr.IN, "__####____"),
                                                           testing::expect("Q", tmr.Q, "____###..."));
    CHECK_FALSE(d);
    CHECK(d.report ==
          "timing diagram: Q differs from cycle 6 (T#60ms)\n"
          "cycle        0123456789\n"
          "IN           __####____\n"
          "Q     expect ____###...\n"
          "      actual ____##____\n"
          "                   ^\n");
  }

  TEST_CASE("value tables line up") {
    CTU counter;
    testing::cycles run{counter};
    const testing::diagram_result d = testing::run_diagram(run, testing::drive("CU", counter.CU, "_#_#_#"),
                                                           testing::drive("PV", counter.PV, "3 . . . . ."),
                                                           testing::expect("CV", counter.CV, "0 1 1 2 2 2"));
    CHECK_FALSE(d);
    CHECK(d.report ==
          "timing diagram: CV differs from cycle 5 (T#50ms)\n"
          "cycle        0     1    2     3    4     5\n"
          "CU           FALSE TRUE FALSE TRUE FALSE TRUE\n"
          "PV           3     .    .     .    .     .\n"
          "CV    expect 0     1    1     2    2     2\n"
          "      actual 0     1    1     2    2     3\n"
          "                                         ^\n");
  }

  TEST_CASE("a diagram over an application") {
    testing::plc<make_plc> plc;
    GVL_IO& io = plc.get<GVL_IO>();
    CHECK(testing::run_diagram(plc, testing::drive("ixButton", io.ixButton, "_########_"),
                               testing::expect("qxLamp", io.qxLamp, "______###_")));
  }

  TEST_CASE("a cell that is no value fails with a message") {
    FB_Div fb;
    testing::cycles run{fb};
    const testing::diagram_result d = testing::run_diagram(run, testing::expect("q", fb.q, "0 x"));
    CHECK_FALSE(d);
    CHECK(d.report.starts_with("timing diagram: iecoop: 'x' in lane q is no value of its type\n"));
  }
}

TEST_SUITE("table") {
  // iecoop-replay's TON trace (tests/replay/ton.trace.csv), worked out by hand from IEC and
  // CODESYS: the same table drives a TON through the kit.
  TEST_CASE("a TON replays the replay tool's trace") {
    TON tmr;
    testing::cycles run{tmr};
    const std::string csv = testing::read_file(IECOOP_SOURCE_DIR "/tests/replay/ton.trace.csv");
    REQUIRE_FALSE(csv.empty());
    const testing::diagram_result r =
        testing::run_table(run, csv, testing::drive("IN", tmr.IN), testing::drive("PT", tmr.PT),
                           testing::expect("Q", tmr.Q), testing::expect("ET", tmr.ET));
    CHECK(r);
    CHECK(r.report == "table: 8 rows as expected");
  }

  TEST_CASE("a differing row is named with its note") {
    TON tmr;
    testing::cycles run{tmr};
    const testing::diagram_result r = testing::run_table(run,
                                                         "cycle,time_ms,IN,PT_ms,Q,ET_ms,note\n"
                                                         "0,0,1,100,0,0,start\n"
                                                         "1,50,1,100,0,50,\n"
                                                         "2,100,1,100,0,100,too late, says the table\n",
                                                         testing::drive("IN", tmr.IN), testing::drive("PT", tmr.PT),
                                                         testing::expect("Q", tmr.Q), testing::expect("ET", tmr.ET));
    CHECK_FALSE(r);
    CHECK(r.report ==
          "table: line 4 (time_ms 100, 'too late, says the table') differs:\n"
          "  Q: expected FALSE, actual TRUE\n"
          "  2,100,1,100,0,100,too late, says the table");
  }

  TEST_CASE_FIXTURE(PlcTest, "a table over an application") {
    const testing::diagram_result r =
        testing::run_table(*this,
                           "cycle,time_ms,ixButton,qxLamp\n"
                           "0,0,1,0\n"
                           "1,50,1,1\n"
                           "2,60,0,0\n",
                           testing::drive("ixButton", io.ixButton), testing::expect("qxLamp", io.qxLamp));
    CHECK(r);
    CHECK(gvl.wPresses == 1U);
  }

  TEST_CASE("a table without a column of a lane") {
    TON tmr;
    testing::cycles run{tmr};
    const testing::diagram_result r = testing::run_table(run, "cycle,time_ms,IN\n0,0,1\n", testing::expect("Q", tmr.Q));
    CHECK_FALSE(r);
    CHECK(r.report == "table: no column Q");
  }
}

namespace {
struct FB_State : function_block<FB_State> {
  var<E_State> eState{E_State::Fault};
  void body() {}
};
}  // namespace

TEST_SUITE("values") {
  TEST_CASE("a failed check prints an enumeration by its name") {
    E_State eState = E_State::Idle;
    const doctest::String text = doctest::toString(eState);
    CHECK(std::string(text.c_str()) == "Idle");
    FB_State fb;
    CHECK(std::string(doctest::toString(fb.eState).c_str()) == "Fault");
  }

  TEST_CASE("a failed check prints an ARRAY as ST writes its initial value") {
    CHECK(printed(ARRAY<INT, 1, 3>{1, 2, 3}) == "[1, 2, 3]");
    CHECK(printed(ARRAY<WORD, 0, 1>{WORD(255)}) == "[16#00FF, 16#0000]");  // elements as in any failed check
    CHECK(printed(ARRAY<STRING<10>, 1, 2>{STRING<10>("it's")}) == "['it$'s', '']");
    CHECK(printed(ARRAY<E_State, 1, 2>{E_State::Run}) == "[Run, Idle]");
    CHECK(printed(ARRAY<BOOL, 1, 2, 1, 2>{TRUE, FALSE, FALSE, TRUE}) == "[TRUE, FALSE, FALSE, TRUE]");  // row by row
    CHECK(printed(ARRAY<ARRAY<INT, 1, 2>, 1, 2>{ARRAY<INT, 1, 2>{1, 2}, ARRAY<INT, 1, 2>{3, 4}}) == "[[1, 2], [3, 4]]");
    CHECK(printed(ARRAY<ST_Range, 1, 2>{ST_Range{INT(1), "T#2s"_iec}}) ==
          "[(iLow := 1, tHold := T#2s), (iLow := 0, tHold := T#0ms)]");
    FB_Sort fb;
    fb.aiValues[2] = 5;
    CHECK(printed(fb.aiValues) == "[0, 5, 0]");  // a block's ARRAY variable
  }
}

TEST_SUITE("forcing") {
  TEST_CASE("release_and_restore gives back the value from before the force") {
    FB_Div fb;
    testing::cycles run{fb};
    fb.a = 8;
    run.force(fb.a, INT(2));
    run.force(fb.a, INT(4));  // forced again: the value before the first force stays
    run.step();
    CHECK(fb.q == 4);
    run.release_and_restore(fb.a);
    CHECK(fb.a == 8);
    CHECK_FALSE(run.forced(fb.a));
    run.step();
    CHECK(fb.q == 8);
  }
}
