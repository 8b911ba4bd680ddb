// iecoop-check fixture: FB_Init, FB_Reinit and FB_Exit that call a method or property a derived
// block overrides (check 6; CODESYS's static analysis rule SA0106, "Virtual method calls in
// FB_init"). iecoop runs FB_Init on the whole block, as CODESYS does: for an FB_Drive,
// FB_Motor's FB_Init runs FB_Drive's Meth_MyInit before FB_Drive's FB_Init has set nRamp.
#include <iecoop/iecoop.hpp>

using namespace iecoop;

// FUNCTION_BLOCK FB_Motor
struct FB_Motor : function_block<FB_Motor> {
  FB_Motor() { run_fb_init(*this); }
  virtual ~FB_Motor() { run_fb_exit(*this); }
  FB_Motor(const FB_Motor&) = default;
  FB_Motor& operator=(const FB_Motor&) = default;

  DINT nSpeed = 0;
  REAL fLimit = 0.0F;
  // METHOD Meth_MyInit : BOOL
  virtual BOOL Meth_MyInit() {
    nSpeed = 100;
    return TRUE;
  }
  // PROPERTY Limit : REAL (Get, Set)
  virtual REAL Limit_Get() { return fLimit; }
  virtual void Limit_Set(REAL value) { fLimit = value; }
  [[no_unique_address]] property<REAL, &FB_Motor::Limit_Get, &FB_Motor::Limit_Set> Limit{this};

  BOOL FB_Init(BOOL, BOOL) {
    Meth_MyInit();         // reported: FB_Drive overrides it
    this->Limit = 10.0F;   // reported: THIS^.Limit, whose Set FB_Drive overrides
    return TRUE;
  }
  BOOL FB_Exit(BOOL);
  virtual BOOL FB_Reinit() { return this->Meth_MyInit(); }  // reported: THIS^.Meth_MyInit()
  virtual void body() {}
};

// Defined outside the class: still FB_Motor's FB_Exit.
BOOL FB_Motor::FB_Exit(BOOL) { return Meth_MyInit(); }  // reported

// FUNCTION_BLOCK FB_Drive EXTENDS FB_Motor
struct FB_Drive : extends<FB_Drive, FB_Motor> {
  FB_Drive() { run_fb_init(*this); }
  ~FB_Drive() override { run_fb_exit(*this); }
  FB_Drive(const FB_Drive&) = default;
  FB_Drive& operator=(const FB_Drive&) = default;

  INT nRamp = 0;
  BOOL Meth_MyInit() override {
    nSpeed = DINT(100 / nRamp);  // nRamp is still 0 when FB_Motor's FB_Init calls it
    return TRUE;
  }
  void Limit_Set(REAL value) override { fLimit = value * REAL(nRamp); }
  BOOL FB_Init(BOOL, BOOL) {
    nRamp = 5;
    return TRUE;
  }
  BOOL FB_Reinit() override { return SUPER::FB_Reinit(); }
  void body() override {}
};
