// Seed: "CoDeSys一些基本概念" (Chinese concepts page), function blocks — "In the example below
// the timer block CMD_TMR is called with values for its parameters IN and PT; the result Q
// is stored in the variable A":
//
//     CMD_TMR(IN := %IX5, PT := 300);
//     A:=CMD_TMR.Q
//
// %IX5 is a directly represented input (IEC's flat bit number: input bit 5, bit 5 of byte 0),
// and PT := 300 is the integer constant 300 for a TIME, i.e. T#300ms. The call stands in a
// program that a cyclic task runs; a simulated field drives input bit 5.
#include <doctest/doctest.h>

#include <iecoop/iecoop.hpp>
#include <iecoop/ostream.hpp>

namespace seed_cmd_tmr {

using namespace iecoop;

// PROGRAM PLC_PRG
struct PLC_PRG : program<PLC_PRG> {
  // VAR CMD_TMR : TON; A : BOOL; END_VAR
  TON CMD_TMR;
  BOOL A;

  void body() {
    CMD_TMR("IN"_ = at<"%IX5">, "PT"_ = 300);  // CMD_TMR(IN := %IX5, PT := 300);
    A = CMD_TMR.Q;                             // A:=CMD_TMR.Q
  }
};

}  // namespace seed_cmd_tmr

using namespace iecoop;
using seed_cmd_tmr::PLC_PRG;

TEST_SUITE("seed: CMD_TMR(IN := %IX5, PT := 300)") {
  TEST_CASE("the timer reads the located input as latched at the start of each cycle") {
    // TASK MainTask (INTERVAL := T#10ms, PRIORITY := 1); PROGRAM Main WITH MainTask : PLC_PRG;
    application plc{task<PLC_PRG>{"MainTask", cyclic{"T#10ms"_iec}, 1}};
    simulated_io<> field;
    plc.connect(field);
    plc.start();
    plc.run_for("T#50ms"_iec);
    CHECK(PLC_PRG::instance().A == FALSE);

    field.set<"%IX5">(TRUE);  // the sensor on input bit 5 switches on at 50 ms
    CHECK(at<"%IX5"> == FALSE);  // not latched yet: the program sees it from the next cycle
    plc.run_for("T#10ms"_iec);
    CHECK(at<"%IX5"> == TRUE);
    CHECK(PLC_PRG::instance().CMD_TMR.IN == TRUE);
    CHECK(PLC_PRG::instance().CMD_TMR.PT == "T#300ms"_iec);

    plc.run_for("T#290ms"_iec);  // cycles at 60 .. 340 ms: ET reaches 290 ms
    CHECK(PLC_PRG::instance().A == FALSE);
    CHECK(PLC_PRG::instance().CMD_TMR.ET == "T#290ms"_iec);
    plc.run_for("T#10ms"_iec);  // the cycle at 350 ms: 300 ms after the edge
    CHECK(PLC_PRG::instance().A == TRUE);

    field.set<"%IX5">(FALSE);
    plc.run_for("T#10ms"_iec);
    CHECK(PLC_PRG::instance().A == FALSE);
  }

  TEST_CASE("%IX5 is bit 5 of input byte 0") {
    default_process_image::clear();
    default_process_image::write<BYTE, "%IB0">(BYTE(0x20));
    CHECK(at<"%IX5"> == TRUE);
    CHECK(at<"%IX0.5"> == TRUE);
    CHECK(at<"%IX4"> == FALSE);
    default_process_image::clear();
  }
}
