// Seed: "CoDeSys一些基本概念" (Chinese concepts page), actions — "动作与其所属的功能块或程序的数据
// 一起工作,使用这个功能块或程序的输入/输出变量和局部变量,没有自己的变量声明。调用动作的格式为
// <Program_name>.<Action_name> 或 <Instance_name>.<Action_name>。如果需要在本身的功能块中调用动作,
// 也即是在动作所属的程序或者功能块中,只需使用动作的名称即可。" (An action works on the data of its
// block or program, with no declarations of its own. It is called as
// <Program_name>.<Action_name> or <Instance_name>.<Action_name>; inside its own block or
// program, by its name alone.) The English page "Object 'Action'" (seed 000) says the same.
//
// The seed gives the three forms without a program. We complete them minimally: FB_Counter
// counts while bPulse is TRUE and has the action Reset; the program PRG_Line counts parts in
// its instance fbParts and has the action A_CloseBatch, which it calls by name after 10 parts;
// PLC_PRG calls PRG_Line and, when the operator asks for it, PRG_Line.A_CloseBatch().
//
// C++: an action is a member function without parameters; a PROGRAM's one instance is
// `PRG_Line::instance()`, so `PRG_Line.A_CloseBatch();` is `PRG_Line::instance().A_CloseBatch();`.
#include <iecoop/testing.hpp>

namespace seed_action_calls {

using namespace iecoop;

// FUNCTION_BLOCK FB_Counter
struct FB_Counter : function_block<FB_Counter> {
  // VAR_INPUT
  BOOL bPulse;  // bPulse : BOOL;
  // END_VAR
  // VAR_OUTPUT
  INT iCount;   // iCount : INT;
  // END_VAR
  using VAR_INPUT = pins<&FB_Counter::bPulse>;
  using VAR_OUTPUT = pins<&FB_Counter::iCount>;

  void body() {
    if (bPulse) {             // IF bPulse THEN
      iCount = iCount + 1;    //     iCount := iCount + 1;
    }                         // END_IF
  }

  // ACTION Reset:
  void Reset() {
    iCount = 0;  // iCount := 0;
  }
};

// PROGRAM PRG_Line
struct PRG_Line : program<PRG_Line> {
  // VAR_INPUT
  BOOL bPart;        // bPart : BOOL;
  // END_VAR
  // VAR_OUTPUT
  INT iParts;        // iParts : INT;
  INT iBatches;      // iBatches : INT;
  // END_VAR
  // VAR
  FB_Counter fbParts;  // fbParts : FB_Counter;
  // END_VAR
  using VAR_INPUT = pins<&PRG_Line::bPart>;
  using VAR_OUTPUT = pins<&PRG_Line::iParts, &PRG_Line::iBatches>;

  void body() {
    fbParts("bPulse"_ = bPart);      // fbParts(bPulse := bPart);
    if (fbParts.iCount >= 10) {      // IF fbParts.iCount >= 10 THEN
      A_CloseBatch();                //     A_CloseBatch();          (in its own program: the name alone)
    }                                // END_IF
    iParts = fbParts.iCount;         // iParts := fbParts.iCount;
  }

  // ACTION A_CloseBatch:
  void A_CloseBatch() {
    iBatches = iBatches + 1;    // iBatches := iBatches + 1;
    fbParts.Reset();            // fbParts.Reset();              <Instance_name>.<Action_name>
    iParts = fbParts.iCount;    // iParts := fbParts.iCount;
  }
};

// PROGRAM PLC_PRG
struct PLC_PRG : program<PLC_PRG> {
  // VAR
  BOOL bSensor;           // bSensor : BOOL;        (a part passes; written online)
  BOOL bCloseBatch;       // bCloseBatch : BOOL;    (the operator closes the batch early)
  var<INT> iParts;        // iParts : INT;
  var<INT> iBatches;      // iBatches : INT;
  // END_VAR

  void body() {
    PRG_Line::instance()("bPart"_ = bSensor, "iParts"_ >> iParts,  // PRG_Line(bPart := bSensor, iParts => iParts,
                         "iBatches"_ >> iBatches);                //          iBatches => iBatches);
    if (bCloseBatch) {                       // IF bCloseBatch THEN
      PRG_Line::instance().A_CloseBatch();   //     PRG_Line.A_CloseBatch();   <Program_name>.<Action_name>
      bCloseBatch = FALSE;                   //     bCloseBatch := FALSE;
    }                                        // END_IF
  }
};

}  // namespace seed_action_calls

using namespace iecoop;
using seed_action_calls::FB_Counter;
using seed_action_calls::PLC_PRG;
using seed_action_calls::PRG_Line;

TEST_SUITE("seed: calling actions, <Program_name>.<Action_name> and <Instance_name>.<Action_name>") {
  TEST_CASE("<Instance_name>.<Action_name>: the action works on the instance's data and does not run its body") {
    FB_Counter fbCounter;
    FB_Counter other;
    testing::cycles run{[&] { fbCounter("bPulse"_ = TRUE); }};
    run.step(3);
    other("bPulse"_ = TRUE);
    CHECK(fbCounter.iCount == 3);
    fbCounter.Reset();  // fbCounter.Reset();   bPulse is still TRUE, yet nothing is counted
    CHECK(fbCounter.iCount == 0);
    CHECK(other.iCount == 1);  // only the instance named
    fbCounter();
    CHECK(fbCounter.iCount == 1);  // the body counts again on the next call
  }

  TEST_CASE("inside its own program, by name: PRG_Line closes a batch after 10 parts") {
    PRG_Line line;
    PLC_PRG plc_prg;
    testing::cycles run{plc_prg};
    plc_prg.bSensor = TRUE;
    run.step(9);
    CHECK(plc_prg.iParts == 9);
    CHECK(plc_prg.iBatches == 0);
    run.step();  // the 10th part: A_CloseBatch();
    CHECK(plc_prg.iParts == 0);
    CHECK(plc_prg.iBatches == 1);
    CHECK(line.fbParts.iCount == 0);
    run.step(25);
    CHECK(plc_prg.iBatches == 3);
    CHECK(plc_prg.iParts == 5);
  }

  TEST_CASE("<Program_name>.<Action_name>: PLC_PRG closes PRG_Line's batch early, without running PRG_Line's body") {
    PRG_Line line;
    PLC_PRG plc_prg;
    testing::cycles run{plc_prg};
    plc_prg.bSensor = TRUE;
    run.step(4);
    CHECK(line.iParts == 4);
    plc_prg.bSensor = FALSE;
    plc_prg.bCloseBatch = TRUE;
    run.step();  // PRG_Line(...) first, counting nothing, then PRG_Line.A_CloseBatch()
    CHECK(plc_prg.bCloseBatch == FALSE);
    CHECK(line.iBatches == 1);  // the program's own data, changed by the action
    CHECK(line.iParts == 0);
    CHECK(line.fbParts.iCount == 0);
    // PLC_PRG read PRG_Line's outputs before the action ran: it sees the change next cycle.
    CHECK(plc_prg.iParts == 4);
    CHECK(plc_prg.iBatches == 0);
    run.step();
    CHECK(plc_prg.iParts == 0);
    CHECK(plc_prg.iBatches == 1);

    // An action called while the inputs say "part": the body does not run, so no part is counted.
    line.bPart = TRUE;
    PRG_Line::instance().A_CloseBatch();  // PRG_Line.A_CloseBatch();
    CHECK(line.iBatches == 2);
    CHECK(line.fbParts.iCount == 0);
  }

  TEST_CASE("the program's action reaches the one instance, whoever calls it") {
    PRG_Line line;
    CHECK(&PRG_Line::instance() == &line);
    PRG_Line::instance()("bPart"_ = TRUE);
    PRG_Line::instance()("bPart"_ = TRUE);
    PRG_Line::instance().A_CloseBatch();
    CHECK(line.iBatches == 1);
    CHECK(line.iParts == 0);
  }
}
