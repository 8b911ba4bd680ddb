// iecoop-check's check 5: a variable of a C++ scalar type (an enum, int, bool, a pointer)
// without an initial value, where ST starts every variable at 0, FALSE or its enumeration's
// first component. iecoop refuses what it sees (a pin, a STRUCT in a var<> or an ARRAY, a
// method's variables); these it does not see.
#include <iecoop/iecoop.hpp>
using namespace iecoop;

enum class E_State : INT::rep { Idle = 1, Run, Fault };

struct ST_Axis {  // TYPE ST_Axis : STRUCT rPos : REAL; eState : E_State; nTries : int; END_STRUCT END_TYPE
  REAL rPos;
  E_State eState;
  int nTries;
};

struct FB_Drive : function_block<FB_Drive> {
  BOOL bRun;
  E_State eLast;      // a VAR that no pins<> names
  bool bSeen;
  INT* pCount;
  E_State eKnown = E_State::Idle;
  void body() {
    E_State eStep;  // VAR_TEMP eStep : E_State; END_VAR
    int i;
    eStep = bRun ? E_State::Run : E_State::Idle;
    i = 1;
    eLast = eStep;
    bSeen = i > 0;
  }
};

struct FB_Params : function_block<FB_Params> {
  explicit FB_Params(INT iAxis) : iAxis_(iAxis), eMode(E_State::Idle) {}
  INT iAxis_;
  E_State eMode;
  E_State eForgot;
  void body() {}
};

struct F_Scale_vars {
  INT iIn;
};
inline constexpr function F_Scale = [](args<F_Scale_vars> in) -> INT {
  double rFactor;  // VAR rFactor : LREAL; END_VAR
  rFactor = 2.0;
  return INT(static_cast<INT::rep>(in.iIn.value() * rFactor));
};

inline int parse_mode(const char* text) {
  E_State eMode;  // an enumeration: reported outside a POU too
  int n = 0;
  eMode = text[0] == 'r' ? E_State::Run : E_State::Idle;
  n = static_cast<int>(eMode);
  return n;
}

enum class E_Step : INT::rep { Start = 10, Done };
inline E_Step eGlobalStep;  // VAR_GLOBAL eGlobalStep : E_Step; END_VAR  (C++: 0, ST: Start)
struct FB_Stepper : function_block<FB_Stepper> {
  static inline E_Step eShared;  // VAR_STAT
  void body() { eShared = E_Step::Done; }
};
