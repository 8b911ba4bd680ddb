// Seed: "CoDeSys一些基本概念" (Chinese concepts page), programs — "A program can be called by
// other POUs; values assigned to its parameters in parentheses after its name, inputs with
// ':=' and outputs with '=>'. A program has no instances: its values persist between calls,
// whoever calls it."
//
// The seed describes the call without code; this is the obvious program: PRG_Counter adds
// its input to a running total, and PLC_PRG calls it with := and =>. The last test runs
// PLC_PRG under a cyclic task, as a controller does:
//
//     TASK MainTask (INTERVAL := T#10ms, PRIORITY := 1);
//     PROGRAM Main WITH MainTask : PLC_PRG;
//
// PRG_Counter is in no task: only PLC_PRG calls it, so it is an ordinary variable.
#include <iecoop/testing.hpp>

namespace seed_program_call {

using namespace iecoop;

// PROGRAM PRG_Counter
struct PRG_Counter : program<PRG_Counter> {
  // VAR_INPUT  iStep : INT; bReset : BOOL; END_VAR
  INT iStep;
  BOOL bReset;
  // VAR_OUTPUT iTotal : INT; END_VAR
  INT iTotal;
  // VAR        iCalls : INT; END_VAR
  var<INT> iCalls;

  using VAR_INPUT = pins<&PRG_Counter::iStep, &PRG_Counter::bReset>;
  using VAR_OUTPUT = pins<&PRG_Counter::iTotal>;

  void body() {
    iCalls = iCalls + 1;      // iCalls := iCalls + 1;
    if (bReset) {             // IF bReset THEN
      iTotal = 0;             //     iTotal := 0;
    } else {                  // ELSE
      iTotal = iTotal + iStep;  //   iTotal := iTotal + iStep;
    }                         // END_IF
  }
};

// PROGRAM PLC_PRG
struct PLC_PRG : program<PLC_PRG> {
  // VAR iResult : INT; END_VAR
  var<INT> iResult;

  void body() {
    INT result;
    PRG_Counter::instance()("iStep"_ = 5, "bReset"_ = FALSE, "iTotal"_ >> result);  // PRG_Counter(iStep := 5, bReset := FALSE, iTotal => iResult);
    iResult = result;
  }
};

}  // namespace seed_program_call

using namespace iecoop;
using seed_program_call::PLC_PRG;
using seed_program_call::PRG_Counter;

TEST_SUITE("seed: PROGRAM called with := and =>") {
  TEST_CASE("a program keeps its values between calls, whoever calls it") {
    PRG_Counter counter;  // the one instance
    PLC_PRG plc_prg;
    plc_prg();
    plc_prg();
    CHECK(plc_prg.iResult == 10);
    // Another caller: inputs not given keep their values (iStep is still 5).
    INT total;
    PRG_Counter::instance()("iTotal"_ >> total);
    CHECK(total == 15);
    CHECK(counter.iCalls == 3);
    PRG_Counter::instance()("bReset"_ = TRUE);
    CHECK(counter.iTotal == 0);
  }

  TEST_CASE("a program has exactly one instance") {
    PRG_Counter first;
    CHECK(&PRG_Counter::instance() == &first);
    {
      testing::expect_faults faults;
      PRG_Counter second;  // a second instance while the first lives: a fault
      CHECK(faults.count(fault_kind::duplicate_program) == 1);
      CHECK(&PRG_Counter::instance() == &first);
    }
    CHECK(PRG_Counter::exists());
  }

  TEST_CASE("under a task: PLC_PRG calls PRG_Counter each cycle with := and =>") {
    PRG_Counter counter;  // the one instance of the program that only PLC_PRG calls
    application plc{task<PLC_PRG>{"MainTask", cyclic{"T#10ms"_iec}, 1}};
    plc.start();
    plc.run_for("T#30ms"_iec);  // cycles at 0, 10 and 20 ms
    CHECK(plc.task("MainTask").statistics().cycles == 3);
    CHECK(counter.iCalls == 3);
    CHECK(PLC_PRG::instance().iResult == 15);
    // Another POU's calls in between change the program's values (0, then 0 + 5: iStep keeps
    // its value); the next cycle goes on from them.
    PRG_Counter::instance()("bReset"_ = TRUE);
    PRG_Counter::instance()("bReset"_ = FALSE);
    plc.run_for("T#10ms"_iec);
    CHECK(PLC_PRG::instance().iResult == 10);
    CHECK(counter.iCalls == 6);
  }
}
