// iecoop-check fixture: a method that uses the block's variable where ST would use its own
// (check 3). In ST, a method's variable hides the block's variable of the same name.
#include <iecoop/iecoop.hpp>

using namespace iecoop;

// FUNCTION_BLOCK FB_Valve
struct FB_Valve : function_block<FB_Valve> {
  BOOL bOpen;                        // VAR_INPUT bOpen : BOOL;
  using VAR_INPUT = pins<&FB_Valve::bOpen>;
  var<INT> nCycles;                  // VAR nCycles : INT;
  var<TIME> tOpen;

  // METHOD Toggle : BOOL
  // VAR_INPUT bOpen : BOOL; END_VAR
  //   Toggle := bOpen;               -- ST's bOpen is the method's input here
  struct Toggle_vars {
    BOOL bOpen;
  };
  BOOL Toggle(args<Toggle_vars> in) { return bOpen; }

  // METHOD Count : INT
  // VAR_INPUT nCycles : INT; END_VAR
  //   Count := nCycles + 1;
  struct Count_vars {
    INT nCycles;
  };
  INT Count(args<Count_vars> request) {
    const auto next = [&] { return nCycles + 1; };  // a lambda in the method: the same
    return next();
  }
  virtual void body() {}
};

// FUNCTION_BLOCK FB_TimedValve EXTENDS FB_Valve: the base's variable, the method's name.
struct FB_TimedValve : extends<FB_TimedValve, FB_Valve> {
  struct Hold_vars {
    TIME tOpen;
  };
  TIME Hold(args<Hold_vars> in);
  void body() override { SUPER::body(); }
};

// METHOD Hold, defined outside the class.
TIME FB_TimedValve::Hold(args<Hold_vars> in) { return tOpen; }
