// iecoop-check fixture, the clean twin of method_variable_shadowed.cpp: a method reads its own
// variable as in.x and the block's as this->x (ST's THIS^.x), or names them differently.
#include <iecoop/iecoop.hpp>

using namespace iecoop;

// FUNCTION_BLOCK FB_Valve
struct FB_Valve : function_block<FB_Valve> {
  BOOL bOpen;
  using VAR_INPUT = pins<&FB_Valve::bOpen>;
  var<INT> nCycles;

  struct Toggle_vars {
    BOOL bOpen;
  };
  // METHOD Toggle : BOOL   Toggle := bOpen XOR THIS^.bOpen;
  BOOL Toggle(args<Toggle_vars> in) { return in.bOpen ^ this->bOpen; }

  struct Count_vars {
    INT nStep;
  };
  // METHOD Count : INT     Count := nCycles + nStep;   (nCycles is the block's: no method variable has its name)
  INT Count(args<Count_vars> in) { return nCycles + in.nStep; }

  // METHOD Reset    VAR_INPUT nCycles : INT; END_VAR    THIS^.nCycles := nCycles;
  struct Reset_vars {
    INT nCycles;
  };
  void Reset(args<Reset_vars> in) {
    const auto assign = [&] { this->nCycles = in.nCycles; };  // in a lambda as well
    assign();
  }
  virtual void body() {}
};

// A class that is no block: its methods are C++'s business.
struct Calculator {
  struct Add_vars {
    INT a;
  };
  INT a;
  INT Add(args<Add_vars> in) { return a + in.a; }
};
