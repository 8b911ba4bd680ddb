// iecoop-check fixture, the clean twin of lifecycle_not_handed_on.cpp: every constructor of a
// block with (or extending a block with) an FB_Init calls run_fb_init(*this, ...) — directly,
// from a template, defined outside the class, or through another constructor it delegates
// to — and every destructor of one with an FB_Exit calls run_fb_exit(*this). Copy and deleted
// constructors, and blocks without FB_Init or FB_Exit, need neither.
#include <iecoop/iecoop.hpp>

#include <utility>

using namespace iecoop;

// FUNCTION_BLOCK FB_Valve, with FB_Init and FB_Exit
struct FB_Valve : function_block<FB_Valve> {
  FB_Valve() { iecoop::run_fb_init(*this); }
  ~FB_Valve() { run_fb_exit(*this); }
  FB_Valve(const FB_Valve&) = default;
  FB_Valve& operator=(const FB_Valve&) = default;
  BOOL bOpen;
  using VAR_INPUT = pins<&FB_Valve::bOpen>;
  BOOL FB_Init(BOOL, BOOL) { return TRUE; }
  BOOL FB_Exit(BOOL) {
    bOpen = FALSE;
    return TRUE;
  }
  void body() {}
};

// FUNCTION_BLOCK FB_Lamp: no FB_Init, no FB_Exit, no constructor.
struct FB_Lamp : function_block<FB_Lamp> {
  BOOL bOn;
  using VAR_INPUT = pins<&FB_Lamp::bOn>;
  void body() {}
};

// FUNCTION_BLOCK FB_Motor
struct FB_Motor : function_block<FB_Motor> {
  FB_Motor() : FB_Motor(INT(0)) {}  // delegates to the one that calls run_fb_init
  explicit FB_Motor(INT id);
  FB_Motor(INT, INT) = delete;
  virtual ~FB_Motor();
  FB_Motor(const FB_Motor&) = default;
  FB_Motor& operator=(const FB_Motor&) = default;
  INT nId = 0;
  BOOL FB_Init(BOOL, BOOL, INT id) {
    nId = id;
    return TRUE;
  }
  BOOL FB_Exit(BOOL) { return TRUE; }
  virtual void body() {}
};
FB_Motor::FB_Motor(INT id) { run_fb_init(*this, id); }
FB_Motor::~FB_Motor() { run_fb_exit(*this); }

// FUNCTION_BLOCK FB_Drive EXTENDS FB_Motor, without FB_Init or FB_Exit of its own
struct FB_Drive : extends<FB_Drive, FB_Motor> {
  explicit FB_Drive(INT id) : extends(id) { run_fb_init(*this, id); }
  ~FB_Drive() override { run_fb_exit(*this); }
  FB_Drive(const FB_Drive&) = default;
  FB_Drive& operator=(const FB_Drive&) = default;
  void body() override {}
};

// FUNCTION_BLOCK FINAL FB_Pump EXTENDS FB_Drive: a constructor template
struct FB_Pump final : extends<FB_Pump, FB_Drive> {
  template <class... A>
  explicit FB_Pump(INT id, A&&... a) : extends(id) {
    run_fb_init(*this, id, std::forward<A>(a)...);
  }
  ~FB_Pump() override { run_fb_exit(*this); }
  void body() override {}
};
