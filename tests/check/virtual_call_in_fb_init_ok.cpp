// iecoop-check fixture, the clean twin of virtual_call_in_fb_init.cpp: FB_Init does its work
// itself or in a method that no block overrides; what it calls on another instance, or as
// SUPER^, is not dispatched on the block; a derived block's own FB_Init may call its own
// methods (no block extends it).
#include <iecoop/iecoop.hpp>

using namespace iecoop;

// FUNCTION_BLOCK FB_Valve
struct FB_Valve : function_block<FB_Valve> {
  virtual BOOL Close() { return TRUE; }
  virtual void body() {}
};

// FUNCTION_BLOCK FB_Motor
struct FB_Motor : function_block<FB_Motor> {
  FB_Motor() { run_fb_init(*this); }
  virtual ~FB_Motor() { run_fb_exit(*this); }
  FB_Motor(const FB_Motor&) = default;
  FB_Motor& operator=(const FB_Motor&) = default;

  DINT nSpeed = 0;
  REAL fLimit = 0.0F;
  FB_Valve fbValve;
  FB_Motor* pNext = nullptr;  // another motor, already initialised
  virtual BOOL Meth_MyInit() {
    nSpeed = 100;
    return TRUE;
  }
  BOOL Reset_Speed() {  // no block overrides it
    nSpeed = 0;
    return TRUE;
  }
  virtual BOOL Log() { return TRUE; }  // virtual, but no block overrides it
  virtual REAL Limit_Get() { return fLimit; }
  virtual void Limit_Set(REAL value) { fLimit = value; }
  [[no_unique_address]] property<REAL, &FB_Motor::Limit_Get, &FB_Motor::Limit_Set> Limit{this};

  BOOL FB_Init(BOOL, BOOL) {
    nSpeed = 100;          // the work itself
    Reset_Speed();         // a method no block overrides
    Log();
    REAL fOld = Limit;     // FB_Drive overrides only Limit's Set
    fLimit = fOld;
    fbValve.Close();       // another instance's method
    if (pNext != nullptr) pNext->Meth_MyInit();
    return TRUE;
  }
  BOOL FB_Exit(BOOL) { return fbValve.Close(); }
  virtual BOOL FB_Reinit() { return TRUE; }
  virtual void body() {}
};

// FUNCTION_BLOCK FB_Drive EXTENDS FB_Motor
struct FB_Drive : extends<FB_Drive, FB_Motor> {
  FB_Drive() { run_fb_init(*this); }
  ~FB_Drive() override { run_fb_exit(*this); }
  FB_Drive(const FB_Drive&) = default;
  FB_Drive& operator=(const FB_Drive&) = default;

  INT nRamp = 0;
  BOOL Meth_MyInit() override {
    nSpeed = DINT(100 / nRamp);
    return TRUE;
  }
  void Limit_Set(REAL value) override { fLimit = value + REAL(1.0F); }
  BOOL FB_Init(BOOL, BOOL) {
    nRamp = 5;
    Meth_MyInit();           // its own override: no block extends FB_Drive
    SUPER::Meth_MyInit();    // SUPER^.Meth_MyInit(): not dispatched
    return TRUE;
  }
  BOOL FB_Reinit() override {
    FB_Motor::FB_Reinit();   // SUPER^.FB_Reinit()
    return this->Meth_MyInit();
  }
  void body() override {}
};
