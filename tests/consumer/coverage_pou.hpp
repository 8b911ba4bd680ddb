// A POU of a user's project whose tests leave one branch untaken (tests/consumer/coverage): the
// coverage report must show the ELSIF's line as a branch taken one way only, and the line in
// it as never run.
#pragma once

#include <iecoop/iecoop.hpp>

namespace plant {

using namespace iecoop;

// FUNCTION_BLOCK FB_Level
// VAR_INPUT rLevel : REAL; END_VAR
// VAR_OUTPUT bHigh, bLow : BOOL; END_VAR
struct FB_Level : function_block<FB_Level> {
  REAL rLevel = 0.0F;
  BOOL bHigh;
  BOOL bLow;
  using VAR_INPUT = pins<&FB_Level::rLevel>;
  using VAR_OUTPUT = pins<&FB_Level::bHigh, &FB_Level::bLow>;

  void body() {
    bHigh = FALSE;                // bHigh := FALSE;
    bLow = FALSE;                 // bLow := FALSE;
    if (rLevel > 90.0F) {         // IF rLevel > 90.0 THEN
      bHigh = TRUE;               //   bHigh := TRUE;
    } else if (rLevel < 10.0F) {  // ELSIF rLevel < 10.0 THEN  (the tests never go below 10)
      bLow = TRUE;                //   bLow := TRUE;            (never run)
    }                             // END_IF
  }
};

}  // namespace plant
