// One feature: the Util library's function manipulators — the documentation's characteristic
// curve (CHARCURVE) fed with a rising counter, and a speed set point whose slope is limited
// (RAMP_REAL per second, RAMP_INT per call).
#include <fmt/core.h>

#include <iecoop/fmt.hpp>
#include <iecoop/iecoop.hpp>

using namespace iecoop;

// PROGRAM CURVE_PRG  (the documentation's example)
struct CURVE_PRG : program<CURVE_PRG> {
  // VAR
  CHARCURVE CHARACTERISTIC_LINE;  // CHARACTERISTIC_LINE : CHARCURVE;
  // KL : ARRAY[0..10] OF POINT := [(X:=0,Y:=0),(X:=250,Y:=50),(X:=500,Y:=150),(X:=750,Y:=400),7((X:=1000,Y:=1000))];
  ARRAY<POINT, 0, 10> KL = {POINT{INT(0), INT(0)},       POINT{INT(250), INT(50)},     POINT{INT(500), INT(150)},
                            POINT{INT(750), INT(400)},   POINT{INT(1000), INT(1000)},  POINT{INT(1000), INT(1000)},
                            POINT{INT(1000), INT(1000)}, POINT{INT(1000), INT(1000)},  POINT{INT(1000), INT(1000)},
                            POINT{INT(1000), INT(1000)}, POINT{INT(1000), INT(1000)}};
  INT COUNTER;  // COUNTER : INT;
  // END_VAR
  void body() {
    COUNTER = COUNTER + 10;  // COUNTER := COUNTER + 10;   (a steadily rising value)
    CHARACTERISTIC_LINE("IN"_ = COUNTER, "N"_ = BYTE(5), "P"_ = KL);  // CHARACTERISTIC_LINE(IN := COUNTER, N := 5, P := KL);
  }
};

// PROGRAM DRIVE_PRG  (every 100 ms)
struct DRIVE_PRG : program<DRIVE_PRG> {
  // VAR
  RAMP_REAL fbSpeed;  // fbSpeed : RAMP_REAL;
  RAMP_INT fbSteps;   // fbSteps : RAMP_INT;
  REAL rSetSpeed;     // rSetSpeed : REAL;
  // END_VAR
  void body() {
    // fbSpeed(IN := rSetSpeed, ASCEND := 25.0, DESCEND := 50.0, TIMEBASE := T#1s);
    fbSpeed("IN"_ = rSetSpeed, "ASCEND"_ = REAL(25.0), "DESCEND"_ = REAL(50.0), "TIMEBASE"_ = "T#1s"_iec);
    // fbSteps(IN := REAL_TO_INT(rSetSpeed), ASCEND := 3, DESCEND := 5);    (per call: TIMEBASE T#0s)
    fbSteps("IN"_ = REAL_TO_INT(rSetSpeed), "ASCEND"_ = INT(3), "DESCEND"_ = INT(5));
  }
};

int main() {
  CURVE_PRG curve;
  fmt::print("COUNTER  OUT  ERR\n");
  for (int call = 1; call <= 105; ++call) {
    curve();
    if (call % 15 == 0 || call == 100 || call == 101) {
      fmt::print("{:>7} {:>4} {:>4}\n", curve.COUNTER, curve.CHARACTERISTIC_LINE.OUT, curve.CHARACTERISTIC_LINE.ERR);
    }
  }
  application plc{task<DRIVE_PRG>{"Drive", cyclic{"T#100ms"_iec}, 1}};
  plc.start();
  DRIVE_PRG& drive = plc.get<DRIVE_PRG>();
  fmt::print("  time | set  | RAMP_REAL | RAMP_INT\n");
  for (int tenth = 0; tenth <= 40; ++tenth) {
    drive.rSetSpeed = REAL(tenth < 25 ? 40.0 : 10.0);
    plc.run_for("T#100ms"_iec);
    if (tenth % 4 == 0) {
      fmt::print("{:>5.1f}s | {:>4.0f} | {:>9.2f} | {:>8}\n", tenth / 10.0, drive.rSetSpeed, drive.fbSpeed.OUT,
                 drive.fbSteps.OUT);
    }
  }
}
