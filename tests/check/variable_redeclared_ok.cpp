// iecoop-check fixture, the clean twin of variable_redeclared.cpp: the derived block uses its
// base's variable and declares only new ones.
#include <iecoop/iecoop.hpp>

using namespace iecoop;

// FUNCTION_BLOCK FB_Tank
struct FB_Tank : function_block<FB_Tank> {
  REAL rLevel;
  using VAR_INPUT = pins<&FB_Tank::rLevel>;
  var<BOOL> bFull;
  virtual void body() { bFull = rLevel > REAL(90.0); }
};

// FUNCTION_BLOCK FB_MixingTank EXTENDS FB_Tank
struct FB_MixingTank : extends<FB_MixingTank, FB_Tank> {
  var<BOOL> bStirring;
  void body() override {
    SUPER::body();
    bStirring = bFull;
  }
};

// Two unrelated blocks may of course use the same names.
struct FB_Silo : function_block<FB_Silo> {
  var<BOOL> bFull;
  void body() {}
};
