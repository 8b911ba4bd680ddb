// One feature: a PROPERTY. Reading it calls Get, assigning it calls Set; a property without
// Set is read-only. It holds no data: the block is as large as its variables.
#include <fmt/core.h>

#include <iecoop/fmt.hpp>
#include <iecoop/iecoop.hpp>

using namespace iecoop;

// FUNCTION_BLOCK FB_Heater
struct FB_Heater : function_block<FB_Heater> {
  var<REAL> rSetpoint{20.0f};  // VAR rSetpoint : REAL := 20.0;
  var<UINT> uiChanges;         //     uiChanges : UINT; END_VAR

  // PROPERTY Setpoint : REAL
  REAL Setpoint_Get() { return rSetpoint; }  // (Get) Setpoint := rSetpoint;
  void Setpoint_Set(REAL value) {            // (Set)
    if (value > 80.0f) {                     // IF Setpoint > 80.0 THEN Setpoint := 80.0; END_IF
      value = 80.0f;
    }
    rSetpoint = value;         // rSetpoint := Setpoint;
    uiChanges = uiChanges + 1;  // uiChanges := uiChanges + 1;
  }
  [[no_unique_address]] property<REAL, &FB_Heater::Setpoint_Get, &FB_Heater::Setpoint_Set> Setpoint{this};

  // PROPERTY Changes : UINT   (Get only)
  UINT Changes_Get() { return uiChanges; }  // (Get) Changes := uiChanges;
  [[no_unique_address]] property<UINT, &FB_Heater::Changes_Get> Changes{this};

  void body() {}
};

int main() {
  FB_Heater fbHeater;  // fbHeater : FB_Heater;
  REAL rNow;           // rNow : REAL;

  rNow = fbHeater.Setpoint;  // rNow := fbHeater.Setpoint;         Get
  fmt::print("initial:   {}\n", rNow);
  fbHeater.Setpoint = 55.5f;  // fbHeater.Setpoint := 55.5;         Set
  fmt::print("set 55.5:  {}\n", fbHeater.Setpoint);
  fbHeater.Setpoint = 95.0f;  // fbHeater.Setpoint := 95.0;         Set limits it
  fmt::print("set 95:    {}\n", fbHeater.Setpoint);
  fbHeater.Setpoint += 0.5f;  // fbHeater.Setpoint := fbHeater.Setpoint + 0.5;   Get, then Set
  fmt::print("+= 0.5:    {}\n", fbHeater.Setpoint);
  if (fbHeater.Changes > 2) {  // IF fbHeater.Changes > 2 THEN
    fmt::print("changes:   {}\n", fbHeater.Changes);
  }
  // fbHeater.Changes := 0;  does not compile: Changes has no Set accessor
  fmt::print("size:      {} bytes (two REAL/UINT variables, the properties add none)\n", sizeof(FB_Heater));
}
