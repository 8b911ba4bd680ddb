// One feature: a FUNCTION_BLOCK. Its inputs, outputs and internal variables keep their values
// from one call to the next; a call assigns inputs by name and copies outputs out.
#include <fmt/core.h>

#include <iecoop/fmt.hpp>
#include <iecoop/iecoop.hpp>

using namespace iecoop;

// FUNCTION_BLOCK FB_Tank
struct FB_Tank : function_block<FB_Tank> {
  // VAR_INPUT
  REAL rInflow;             // rInflow : REAL;
  REAL rOutflow;            // rOutflow : REAL;
  REAL rCapacity = 100.0f;  // rCapacity : REAL := 100.0;
  // END_VAR
  // VAR_OUTPUT
  REAL rLevel;  // rLevel : REAL;
  BOOL bFull;   // bFull : BOOL;
  // END_VAR
  // VAR
  var<UDINT> udiCalls;  // udiCalls : UDINT;
  // END_VAR
  using VAR_INPUT = pins<&FB_Tank::rInflow, &FB_Tank::rOutflow, &FB_Tank::rCapacity>;
  using VAR_OUTPUT = pins<&FB_Tank::rLevel, &FB_Tank::bFull>;

  void body() {
    udiCalls = udiCalls + 1;               // udiCalls := udiCalls + 1;
    rLevel = rLevel + rInflow - rOutflow;  // rLevel := rLevel + rInflow - rOutflow;
    if (rLevel > rCapacity) {              // IF rLevel > rCapacity THEN
      rLevel = rCapacity;                  //     rLevel := rCapacity;
    }                                      // END_IF
    if (rLevel < 0.0f) {                   // IF rLevel < 0.0 THEN
      rLevel = 0.0f;                       //     rLevel := 0.0;
    }                                      // END_IF
    bFull = rLevel >= rCapacity;           // bFull := rLevel >= rCapacity;
  }
};

int main() {
  FB_Tank fbTank;  // fbTank : FB_Tank;
  BOOL bFull;      // bFull : BOOL;

  for (int i = 0; i < 5; ++i) {
    // fbTank(rInflow := 30.0, rOutflow := 5.0, bFull => bFull);
    fbTank("rInflow"_ = 30.0f, "rOutflow"_ = 5.0f, "bFull"_ >> bFull);
    fmt::print("call {}: level {:5.1f}  full {}\n", fbTank.udiCalls, fbTank.rLevel, bFull);
  }

  // An input left out of a call keeps its value: rOutflow is still 5.0.
  fbTank.rInflow = 0.0f;  // fbTank.rInflow := 0.0;
  fbTank();               // fbTank();
  fmt::print("call {}: level {:5.1f}  full {}\n", fbTank.udiCalls, fbTank.rLevel, fbTank.bFull);
}
