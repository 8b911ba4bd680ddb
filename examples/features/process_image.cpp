// One feature: located variables and the process image. The program reads %I and writes %Q
// through variables declared AT an address; the application latches the inputs at the start
// of each cycle and sends the outputs at its end, here to a simulated field.
#include <fmt/core.h>

#include <iecoop/fmt.hpp>
#include <iecoop/iecoop.hpp>

using namespace iecoop;

// PROGRAM PLC_PRG
struct PLC_PRG : program<PLC_PRG> {
  // VAR
  [[no_unique_address]] located<BOOL, "%IX0.0"> bStart;     // bStart AT %IX0.0 : BOOL;
  [[no_unique_address]] located<BOOL, "%IX0.1"> bStop;      // bStop AT %IX0.1 : BOOL;    (NC contact)
  [[no_unique_address]] located<INT, "%IW1"> iSpeed;        // iSpeed AT %IW1 : INT;
  [[no_unique_address]] located<BOOL, "%QX0.0"> bMotor;     // bMotor AT %QX0.0 : BOOL;
  [[no_unique_address]] located<INT, "%QW1"> iReference;    // iReference AT %QW1 : INT;
  RS rsRun;                                                 // rsRun : RS;
  // END_VAR
  using LOCATED = pins<&PLC_PRG::bStart, &PLC_PRG::bStop, &PLC_PRG::iSpeed, &PLC_PRG::bMotor, &PLC_PRG::iReference>;

  void body() {
    rsRun("S"_ = bStart, "R1"_ = !bStop);  // rsRun(S := bStart, R1 := NOT bStop);
    bMotor = rsRun.Q1;                     // bMotor := rsRun.Q1;
    if (bMotor) {                          // IF bMotor THEN
      iReference = iSpeed * 2;             //     iReference := iSpeed * 2;
    } else {                               // ELSE
      iReference = 0;                      //     iReference := 0;
    }                                      // END_IF
  }
};

simulated_io<> field;  // the terminals, as the field sees them

void show(application<task<PLC_PRG>>& plc, const char* what) {
  plc.run_for("T#10ms"_iec);  // one cycle
  fmt::print("{:<28} %QX0.0 {:<5}  %QW1 {}\n", what, field.output<"%QX0.0">(), field.get<INT, "%QW1">());
}

int main() {
  application plc{task<PLC_PRG>{"Main", cyclic{"T#10ms"_iec}, 1}};
  plc.connect(field);
  plc.start();

  field.set<"%IX0.1">(TRUE);  // the stop button is closed (not pressed)
  field.set<"%IW1">(INT(300));
  show(plc, "idle");
  field.set<"%IX0.0">(TRUE);
  show(plc, "start pressed");
  field.set<"%IX0.0">(FALSE);
  field.set<"%IW1">(INT(450));
  show(plc, "start released, speed 450");
  WORD wReference = at<"%QW1">;  // wReference := %QW1;   the same bytes, as a direct address
  fmt::print("%QW1 read directly as a WORD: {}\n", wReference);
  field.set<"%IX0.1">(FALSE);
  show(plc, "stop pressed");
  plc.stop();
}
