// iecoop-check fixture, the clean twin of hidden_method.cpp: every method of a base block that
// a derived block redefines is virtual and overridden; what is not dispatched is left alone.
#include <iecoop/iecoop.hpp>

using namespace iecoop;

// INTERFACE I_Count
struct I_Count : interface_base<I_Count> {
  virtual INT Count() = 0;
};

// FUNCTION_BLOCK FB_Base IMPLEMENTS I_Count
struct FB_Base : function_block<FB_Base, implements<I_Count>> {
  var<INT> nCount;
  struct M_vars {
    INT x;
  };
  FB_Base() { run_fb_init(*this); }
  ~FB_Base() { run_fb_exit(*this); }
  BOOL FB_Init(BOOL, BOOL) { return TRUE; }     // lifecycle: called on the block's own type
  BOOL FB_Exit(BOOL) { return TRUE; }
  virtual INT M(args<M_vars> in) { return in.x; }
  INT Count() override { return nCount; }
  INT Helper() { return nCount; }                 // not redefined below: fine
  static INT Make() { return 1; }                 // static: not a method of an instance
  FB_Base& operator=(const FB_Base&) = default;
  virtual void body() {}
};

// FUNCTION_BLOCK FB_Derived EXTENDS FB_Base
struct FB_Derived : extends<FB_Derived, FB_Base> {
  FB_Derived() { run_fb_init(*this); }
  ~FB_Derived() { run_fb_exit(*this); }
  BOOL FB_Init(BOOL, BOOL) { return TRUE; }
  BOOL FB_Exit(BOOL) { return TRUE; }
  INT M(args<M_vars> in) override { return SUPER::M(in) + 1; }
  INT Count() override { return nCount + 1; }
  INT Other() { return Helper(); }
  static INT Make() { return 2; }
  void body() override { SUPER::body(); }
};

// A class that is no block may hide what it likes (C++'s own rules).
struct Plain {
  INT M() { return 1; }
};
struct PlainDerived : Plain {
  INT M() { return 2; }
};
