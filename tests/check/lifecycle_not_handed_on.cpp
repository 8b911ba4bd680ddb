// iecoop-check fixture: blocks whose constructor does not call run_fb_init(*this, ...) or whose
// destructor does not call run_fb_exit(*this) although they have, or EXTEND a block that has,
// an FB_Init or FB_Exit (check 7). iecoop runs FB_Init and FB_Exit only from there: a block of
// its own never runs them; for a block that EXTENDS another, no level runs them on the whole
// block (a lifecycle fault at run time).
#include <iecoop/iecoop.hpp>

using namespace iecoop;

// FUNCTION_BLOCK FB_Valve, with FB_Init and FB_Exit: neither ever runs.
struct FB_Valve : function_block<FB_Valve> {
  BOOL bOpen;
  using VAR_INPUT = pins<&FB_Valve::bOpen>;
  DINT nCycles = 0;
  BOOL FB_Init(BOOL, BOOL) {  // reported at the class: no constructor of its own
    nCycles = 0;
    return TRUE;
  }
  BOOL FB_Exit(BOOL) {  // reported at the class: no destructor of its own
    bOpen = FALSE;
    return TRUE;
  }
  void body() {}
};

// FUNCTION_BLOCK FB_Motor
struct FB_Motor : function_block<FB_Motor> {
  FB_Motor() { run_fb_init(*this); }
  explicit FB_Motor(INT id) : nId(id) {}  // reported: does not call run_fb_init
  virtual ~FB_Motor() = default;           // reported: does not call run_fb_exit
  FB_Motor(const FB_Motor&) = default;
  FB_Motor& operator=(const FB_Motor&) = default;
  INT nId = 0;
  BOOL FB_Init(BOOL, BOOL) { return TRUE; }
  BOOL FB_Exit(BOOL) { return TRUE; }
  virtual void body() {}
};

// FUNCTION_BLOCK FB_Drive EXTENDS FB_Motor: no FB_Init or FB_Exit of its own, but its levels'
// run only from its constructor and destructor.
struct FB_Drive : extends<FB_Drive, FB_Motor> {
  using extends::extends;  // reported at the class: an inherited constructor cannot call run_fb_init
  ~FB_Drive() override {}  // reported: does not call run_fb_exit
  void body() override {}
};

// FUNCTION_BLOCK FB_Pump EXTENDS FB_Motor
struct FB_Pump : extends<FB_Pump, FB_Motor> {
  FB_Pump() = default;  // reported
  ~FB_Pump() override { run_fb_exit(*this); }
  void body() override {}
};
