// iecoop-check fixture: a derived block that declares a variable its base block declares
// (check 4). CODESYS rejects it; in C++ the base's code and the derived block's code would
// use two different variables of the same name.
#include <iecoop/iecoop.hpp>

using namespace iecoop;

// FUNCTION_BLOCK FB_Tank
struct FB_Tank : function_block<FB_Tank> {
  REAL rLevel;                        // VAR_INPUT
  using VAR_INPUT = pins<&FB_Tank::rLevel>;
  var<BOOL> bFull;                    // VAR
  virtual void body() { bFull = rLevel > REAL(90.0); }
};

// FUNCTION_BLOCK FB_MixingTank EXTENDS FB_Tank
struct FB_MixingTank : extends<FB_MixingTank, FB_Tank> {
  var<BOOL> bFull;                    // FB_Tank's bFull again
  var<BOOL> bStirring;
  void body() override {
    SUPER::body();
    bStirring = bFull;
  }
};
