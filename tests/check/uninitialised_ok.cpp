// The clean twin of uninitialised.cpp: every variable states its initial value, or has an IEC
// type (whose own initial value is ST's), or is initialised by a constructor; a union states
// its constructor; a class with constructors of its own is not a STRUCT.
#include <cstdlib>

#include <iecoop/iecoop.hpp>
using namespace iecoop;

enum class E_State : INT::rep { Idle = 1, Run, Fault };
template <>
inline constexpr auto iecoop::enum_components<E_State> = components<E_State::Idle, E_State::Run, E_State::Fault>{};

struct ST_Axis {
  REAL rPos;
  E_State eState = E_State::Idle;
  int nTries = 0;
};

union U_Word {
  WORD w;
  unsigned char ab[2];
  constexpr U_Word() : w() {}
};

class ring_buffer {  // C++ of its own: not a STRUCT
 public:
  ring_buffer() { count_ = 0; }

 private:
  int count_;
};

struct FB_Drive : function_block<FB_Drive> {
  BOOL bRun;
  var<E_State> eLast;
  BOOL bSeen;
  POINTER_TO<INT> pCount;
  E_State eKnown = E_State::Idle;
  ARRAY<E_State, 1, 3> aeStates;
  void body() {
    E_State eStep = E_State::Idle;
    INT i;
    static int calls;
    ++calls;
    for (const E_State e : aeStates) eStep = e;
    eStep = bRun ? E_State::Run : eStep;
    i = 1;
    eLast = eStep;
    bSeen = i > 0;
  }
};

struct FB_Params : function_block<FB_Params> {
  explicit FB_Params(INT iAxis) : iAxis_(iAxis), eMode(E_State::Idle) {}
  INT iAxis_;
  E_State eMode;
  void body() {}
};

struct F_Scale_vars {
  INT iIn;
};
inline constexpr function F_Scale = [](args<F_Scale_vars> in) -> INT {
  LREAL rFactor;
  rFactor = 2.0;
  return LREAL_TO_INT(INT_TO_LREAL(in.iIn) * rFactor);
};

inline long parse_number(const char* text) {  // C++ around a port: its int locals are C++'s
  char* end;
  const long n = std::strtol(text, &end, 10);
  return *end == '\0' ? n : -1;
}

enum class E_Step : INT::rep { Start = 10, Done };
enum class E_Zero : INT::rep { First, Second };
inline E_Step eGlobalStep = E_Step::Start;
inline E_Zero eGlobalZero;  // zero-initialised: its first component
struct FB_Stepper : function_block<FB_Stepper> {
  static inline E_Step eShared = E_Step::Start;
  void body() { eShared = E_Step::Done; }
};
