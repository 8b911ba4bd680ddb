// One feature: the Util library's mathematical blocks — a tank's level scaled from its sensor's
// volts (LIN_TRAFO), its rate of change (DERIVATIVE) and the volume pumped out (INTEGRAL of the
// flow), and the level's minimum, maximum, mean (STATISTICS_REAL, STATISTICS_INT) and variance.
#include <fmt/core.h>

#include <iecoop/fmt.hpp>
#include <iecoop/iecoop.hpp>

using namespace iecoop;

// PROGRAM TANK_PRG  (called every 100 ms)
struct TANK_PRG : program<TANK_PRG> {
  // VAR
  REAL rVolt;                 // rVolt : REAL;          (the level sensor, 0..10 V)
  REAL rFlow;                 // rFlow : REAL;          (the outlet, litres per second)
  LIN_TRAFO fbScale;          // fbScale : LIN_TRAFO;
  DERIVATIVE fbRate;          // fbRate : DERIVATIVE;
  INTEGRAL fbVolume;          // fbVolume : INTEGRAL;
  STATISTICS_REAL fbLevel;    // fbLevel : STATISTICS_REAL;
  STATISTICS_INT fbLevelInt;  // fbLevelInt : STATISTICS_INT;
  VARIANCE fbSpread;          // fbSpread : VARIANCE;
  REAL rLevel;                // rLevel : REAL;         (cm)
  BOOL bFirst = TRUE;         // bFirst : BOOL := TRUE;
  // END_VAR
  void body() {
    // fbScale(IN := rVolt, IN_MIN := 0, IN_MAX := 10, OUT_MIN := 0, OUT_MAX := 250);
    fbScale("IN"_ = rVolt, "IN_MIN"_ = REAL(0.0), "IN_MAX"_ = REAL(10.0), "OUT_MIN"_ = REAL(0.0),
            "OUT_MAX"_ = REAL(250.0));
    rLevel = fbScale.OUT;                                            // rLevel := fbScale.OUT;
    fbRate("IN"_ = rLevel, "TM"_ = DWORD(100), "RESET"_ = bFirst);   // fbRate(IN := rLevel, TM := 100, RESET := bFirst);
    fbVolume("IN"_ = rFlow, "TM"_ = DWORD(100), "RESET"_ = bFirst);  // fbVolume(IN := rFlow, TM := 100, RESET := bFirst);
    fbLevel("IN"_ = rLevel);                                         // fbLevel(IN := rLevel);
    fbLevelInt("IN"_ = REAL_TO_INT(rLevel));                         // fbLevelInt(IN := REAL_TO_INT(rLevel));
    fbSpread("IN"_ = rLevel, "RESET"_ = bFirst);                     // fbSpread(IN := rLevel, RESET := bFirst);
    bFirst = FALSE;                                                  // bFirst := FALSE;
  }
};

int main() {
  TANK_PRG tank;
  fmt::print("  time | volts | level cm | rate cm/s | pumped l | min    max    mean   | int mean | variance\n");
  for (int tenth = 0; tenth <= 50; ++tenth) {
    // The level falls 2 cm/s for 3 s (the pump on: 1.5 l/s), then stays.
    const double seconds = tenth / 10.0;
    const double level = seconds < 3.0 ? 200.0 - 2.0 * seconds : 194.0;
    tank.rVolt = REAL(static_cast<float>(level / 25.0));
    tank.rFlow = REAL(seconds < 3.0 ? 1.5F : 0.0F);
    tank();
    if (tenth % 5 == 0) {
      fmt::print("{:>5.1f}s | {:>5.2f} | {:>8.2f} | {:>9.2f} | {:>8.2f} | {:>6.2f} {:>6.2f} {:>6.2f} | {:>8} | {:>8.3f}\n",
                 seconds, tank.rVolt, tank.rLevel, tank.fbRate.OUT, tank.fbVolume.OUT, tank.fbLevel.MN,
                 tank.fbLevel.MX, tank.fbLevel.AVG, tank.fbLevelInt.AVG, tank.fbSpread.OUT);
    }
  }
  tank.rVolt = REAL(12.0);  // beyond the sensor's range
  tank();
  fmt::print("12 V: level {:.1f} cm, ERROR {}\n", tank.rLevel, tank.fbScale.ERROR);
}
