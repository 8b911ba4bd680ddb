// One feature: the Util library's controllers — an oven held at its set point by a PID in a
// 100 ms task, the heater limited to 0..100 %, a set point raised halfway, a door opened (heat
// lost) near the end; and the same oven under PID_FIXCYCLE, which is told its cycle (docs/util.md).
#include <fmt/core.h>

#include <iecoop/fmt.hpp>
#include <iecoop/iecoop.hpp>

using namespace iecoop;

// The oven: a first-order plant, T' = (20 + 0.9 * heater - T) / 60 s (20 degrees ambient, 90
// degrees more at full power), integrated each cycle; bDoorOpen loses 25 degrees' worth.
struct oven {
  double temperature = 20.0;
  void step(double heater_percent, bool door_open, double seconds) {
    const double target = 20.0 + 0.9 * heater_percent - (door_open ? 25.0 : 0.0);
    temperature += (target - temperature) * seconds / 60.0;
  }
};

// PROGRAM TEMP_PRG
struct TEMP_PRG : program<TEMP_PRG> {
  // VAR
  PID fbPID;             // fbPID : PID;
  REAL rTemp;            // rTemp : REAL;           (from the sensor)
  REAL rSetPoint = 80;   // rSetPoint : REAL := 80;
  REAL rHeater;          // rHeater : REAL;         (to the heater, %)
  // END_VAR
  void body() {
    // fbPID(ACTUAL := rTemp, SET_POINT := rSetPoint, KP := 8.0, TN := 40.0, TV := 2.0,
    //       Y_MIN := 0.0, Y_MAX := 100.0);
    fbPID("ACTUAL"_ = rTemp, "SET_POINT"_ = rSetPoint, "KP"_ = REAL(8.0), "TN"_ = REAL(40.0), "TV"_ = REAL(2.0),
          "Y_MIN"_ = REAL(0.0), "Y_MAX"_ = REAL(100.0));
    rHeater = fbPID.Y;  // rHeater := fbPID.Y;
  }
};

int main() {
  // TASK Main (INTERVAL := T#100ms, PRIORITY := 1);  PROGRAM Temp WITH Main : TEMP_PRG;
  application plc{task<TEMP_PRG>{"Main", cyclic{"T#100ms"_iec}, 1}};
  plc.start();
  TEMP_PRG& temp = plc.get<TEMP_PRG>();
  oven plant;
  fmt::print("  time | set point | temperature | heater % | limited\n");
  for (int tenth = 0; tenth <= 6000; ++tenth) {  // ten minutes of machine time
    if (tenth == 3000) temp.rSetPoint = REAL(100.0);
    const bool door_open = tenth >= 5000 && tenth < 5300;
    temp.rTemp = REAL(static_cast<float>(plant.temperature));
    plc.run_for("T#100ms"_iec);
    plant.step(static_cast<double>(temp.rHeater.value()), door_open, 0.1);
    if (tenth % 300 == 0) {
      fmt::print("{:>5}s | {:>9.1f} | {:>11.2f} | {:>8.2f} | {}\n", tenth / 10, temp.rSetPoint.value(),
                 plant.temperature, temp.rHeater.value(), temp.fbPID.LIMITS_ACTIVE);
    }
  }
  // The same controller told its cycle: PID_FIXCYCLE, called by hand every 100 ms.
  PID_FIXCYCLE fbFix;
  oven second;
  for (int tenth = 0; tenth < 3000; ++tenth) {
    fbFix("ACTUAL"_ = REAL(static_cast<float>(second.temperature)), "SET_POINT"_ = REAL(80.0), "KP"_ = REAL(8.0),
          "TN"_ = REAL(40.0), "TV"_ = REAL(2.0), "Y_MIN"_ = REAL(0.0), "Y_MAX"_ = REAL(100.0), "CYCLE"_ = REAL(0.1));
    second.step(static_cast<double>(fbFix.Y.get().value()), false, 0.1);
  }
  fmt::print("PID_FIXCYCLE after 300 s: {:.2f} degrees, heater {:.2f} %\n", second.temperature, fbFix.Y);
}
