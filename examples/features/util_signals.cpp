// One feature: the Util library's signal blocks — a warning lamp that blinks (BLINK), a test
// signal (GEN: a triangle over the time, a sine over the calls) and the frequency of a
// pulse train measured (FREQ_MEASURE), each in a 10 ms task.
#include <fmt/core.h>

#include <iecoop/fmt.hpp>
#include <iecoop/iecoop.hpp>

using namespace iecoop;

// PROGRAM SIGNAL_PRG
struct SIGNAL_PRG : program<SIGNAL_PRG> {
  // VAR
  BLINK fbLamp;          // fbLamp : BLINK;
  GEN fbTriangle;        // fbTriangle : GEN;
  GEN fbSine;            // fbSine : GEN;
  FREQ_MEASURE fbFreq;   // fbFreq : FREQ_MEASURE;
  BOOL bAlarm;           // bAlarm : BOOL;
  BOOL bPulse;           // bPulse : BOOL;          (from a sensor)
  // END_VAR
  void body() {
    // fbLamp(ENABLE := bAlarm, TIMELOW := T#60ms, TIMEHIGH := T#40ms);
    fbLamp("ENABLE"_ = bAlarm, "TIMELOW"_ = "T#60ms"_iec, "TIMEHIGH"_ = "T#40ms"_iec);
    // fbTriangle(MODE := GEN_MODE.TRIANGLE, BASE := TRUE, PERIOD := T#200ms, AMPLITUDE := 100);
    fbTriangle("MODE"_ = GEN_MODE::TRIANGLE, "BASE"_ = TRUE, "PERIOD"_ = "T#200ms"_iec, "AMPLITUDE"_ = INT(100));
    // fbSine(MODE := GEN_MODE.SINE, BASE := FALSE, CYCLES := 12, AMPLITUDE := 50);
    fbSine("MODE"_ = GEN_MODE::SINE, "BASE"_ = FALSE, "CYCLES"_ = INT(12), "AMPLITUDE"_ = INT(50));
    fbFreq("IN"_ = bPulse, "PERIODS"_ = INT(2));  // fbFreq(IN := bPulse, PERIODS := 2);
  }
};

int main() {
  // TASK Fast (INTERVAL := T#10ms, PRIORITY := 0);  PROGRAM Signals WITH Fast : SIGNAL_PRG;
  application plc{task<SIGNAL_PRG>{"Fast", cyclic{"T#10ms"_iec}, 0}};
  plc.start();
  SIGNAL_PRG& prg = plc.get<SIGNAL_PRG>();
  fmt::print("  ms | lamp  | triangle | sine | pulse | Hz     valid\n");
  for (int cycle = 0; cycle < 40; ++cycle) {
    prg.bAlarm = cycle >= 2;
    prg.bPulse = cycle % 5 == 0 || (cycle >= 20 && cycle % 5 == 1);  // an edge every 50 ms
    plc.run_for("T#10ms"_iec);
    fmt::print("{:>4} | {:<5} | {:>8} | {:>4} | {:<5} | {:>6.2f} {}\n", cycle * 10, prg.fbLamp.OUT, prg.fbTriangle.OUT,
               prg.fbSine.OUT, prg.bPulse, prg.fbFreq.OUT, prg.fbFreq.VALID);
  }
}
