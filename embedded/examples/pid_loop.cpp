// Firmware example: a PID loop from the Util library (docs/util.md). A PROGRAM called every
// 10 ms, the cycle clock set before each call as a task would, holds a first-order plant (a
// heater and its temperature, simulated in REAL) at its set point: from 20 to 80 degrees with
// the heater limited to 0..100 %, a set point raised to 90 at 30 s, a loss of heat from 45 s.
// A CHARCURVE maps the heater's per mille onto a PWM duty, a STATISTICS_INT follows the
// temperature: integer blocks whose divisions the image must make without libgcc's 64-bit
// routine (test no_64bit_division).
// main() prints the temperature every 10 s and checks that the heater hit its limit at the
// start, that the anti-windup kept the overshoot under one degree, and that the loop settled
// at the new set point despite the loss.
#include <iecoop/iecoop.hpp>

#include "console.hpp"
#include "exit_status.hpp"
#include "fault_handler.hpp"

namespace {

using namespace iecoop;

// PROGRAM TEMP_PRG
struct TEMP_PRG : program<TEMP_PRG> {
  // VAR
  PID fbPID;               // fbPID : PID;
  CHARCURVE fbDuty;        // fbDuty : CHARCURVE;
  STATISTICS_INT fbStats;  // fbStats : STATISTICS_INT;
  REAL rTemp;              // rTemp : REAL;            (the sensor)
  REAL rSetPoint = 80;     // rSetPoint : REAL := 80;
  REAL rHeater;            // rHeater : REAL;          (the heater, %)
  INT iDuty;               // iDuty : INT;             (the heater's PWM, 0..255)
  // aCurve : ARRAY[0..10] OF POINT := [(X:=0,Y:=0), (X:=500,Y:=96), (X:=1000,Y:=255)];
  ARRAY<POINT, 0, 10> aCurve = {POINT{INT(0), INT(0)}, POINT{INT(500), INT(96)}, POINT{INT(1000), INT(255)}};
  // END_VAR

  void body() {
    // fbPID(ACTUAL := rTemp, SET_POINT := rSetPoint, KP := 6.0, TN := 4.0, TV := 0.5,
    //       Y_MIN := 0.0, Y_MAX := 100.0);
    fbPID("ACTUAL"_ = rTemp, "SET_POINT"_ = rSetPoint, "KP"_ = 6.0, "TN"_ = 4.0, "TV"_ = 0.5, "Y_MIN"_ = 0.0,
          "Y_MAX"_ = 100.0);
    rHeater = fbPID.Y;  // rHeater := fbPID.Y;
    // fbDuty(IN := REAL_TO_INT(rHeater * 10.0), N := 3, P := aCurve);   (per mille to the PWM's duty)
    fbDuty("IN"_ = REAL_TO_INT(rHeater * REAL(10.0)), "N"_ = 3, "P"_ = aCurve);
    iDuty = fbDuty.OUT;                   // iDuty := fbDuty.OUT;
    fbStats("IN"_ = REAL_TO_INT(rTemp));  // fbStats(IN := REAL_TO_INT(rTemp));
  }
};

TEMP_PRG oven;

// The plant: T' = (20 + 1.2 x heater - loss - T) / 8 s, Euler steps of 10 ms.
struct heater_plant {
  float temperature = 20.0F;
  void step(float heater, float loss) {
    const float target = 20.0F + 1.2F * heater - loss;
    temperature = temperature + (target - temperature) * (0.01F / 8.0F);
  }
};

}  // namespace

int main() {
  firmware::install_fault_handler();
  heater_plant plant;
  long limited_until = -1;  // the last cycle (ms) at which the heater was at a limit, in the first 30 s
  float highest = 0.0F;     // the highest temperature before the set point changed
  for (long t = 0; t <= 60000; t += 10) {
    cycle_clock::set(LTIME::from_ticks(static_cast<std::uint64_t>(t) * 1000000U));  // ms in ns
    if (t == 30000) oven.rSetPoint = REAL(90.0);
    oven.rTemp = REAL(plant.temperature);
    oven();
    plant.step(oven.rHeater.value(), t >= 45000 ? 15.0F : 0.0F);
    if (t < 30000) {
      if (oven.fbPID.LIMITS_ACTIVE) limited_until = t;
      if (plant.temperature > highest) highest = plant.temperature;
    }
    if (t % 10000 == 0) {
      firmware::print_line(t / 1000, " s: set point ", oven.rSetPoint, ", temperature ", REAL(plant.temperature),
                           ", heater ", oven.rHeater, " %");
    }
  }
  firmware::print_line("heater at its limit until ", limited_until, " ms; highest before 30 s: ", REAL(highest));
  firmware::print_line("PWM duty now ", oven.iDuty, "; temperature min ", oven.fbStats.MN.get(), ", max ",
                       oven.fbStats.MX.get(), ", mean ", oven.fbStats.AVG.get());
  const float error = plant.temperature - 90.0F;
  const bool ok = limited_until > 0 && limited_until < 10000 && highest < 81.0F && error < 0.1F && error > -0.1F &&
                  oven.fbPID.OVERFLOW == FALSE;
  firmware::print_line("RESULT pid_loop ", ok ? "PASS" : "FAIL");
  return ok ? firmware::exit_status::passed : firmware::exit_status::failed;
}
