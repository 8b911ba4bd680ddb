// One feature: the Util library's analog monitors — a heater switched by HYSTERESIS (on below
// 200, off above 220) and a tank level watched by LIMITALARM.
#include <fmt/core.h>

#include <iecoop/fmt.hpp>
#include <iecoop/iecoop.hpp>

using namespace iecoop;

// PROGRAM MONITOR_PRG
struct MONITOR_PRG : program<MONITOR_PRG> {
  // VAR
  HYSTERESIS fbHeater;  // fbHeater : HYSTERESIS;
  LIMITALARM fbLevel;   // fbLevel : LIMITALARM;
  INT iTemp;            // iTemp : INT;
  INT iLevel;           // iLevel : INT;
  BOOL bHeater;         // bHeater : BOOL;
  // END_VAR
  void body() {
    fbHeater("IN"_ = iTemp, "HIGH"_ = INT(220), "LOW"_ = INT(200));   // fbHeater(IN := iTemp, HIGH := 220, LOW := 200);
    bHeater = fbHeater.OUT;                                           // bHeater := fbHeater.OUT;
    fbLevel("IN"_ = iLevel, "HIGH"_ = INT(900), "LOW"_ = INT(100));  // fbLevel(IN := iLevel, HIGH := 900, LOW := 100);
  }
};

int main() {
  MONITOR_PRG prg;
  const int temps[] = {210, 199, 205, 215, 220, 221, 210, 200, 199};
  const int levels[] = {500, 950, 900, 901, 100, 99, 50, 500, 1000};
  fmt::print("temp heater | level  O      U      IL\n");
  for (int i = 0; i < 9; ++i) {
    prg.iTemp = INT(static_cast<std::int16_t>(temps[i]));
    prg.iLevel = INT(static_cast<std::int16_t>(levels[i]));
    prg();
    fmt::print("{:>4} {:<6} | {:>5}  {:<6} {:<6} {}\n", prg.iTemp, prg.bHeater, prg.iLevel, prg.fbLevel.O,
               prg.fbLevel.U, prg.fbLevel.IL);
  }
}
