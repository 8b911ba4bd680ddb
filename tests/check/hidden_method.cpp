// iecoop-check fixture: methods that hide their base block's method instead of overriding it
// (check 1). CODESYS dispatches every METHOD virtually; C++ only a virtual one.
#include <iecoop/iecoop.hpp>

using namespace iecoop;

// FUNCTION_BLOCK FB_Base
struct FB_Base : function_block<FB_Base> {
  var<INT> nCount;
  struct M_vars {
    INT x;
  };
  struct Scale_vars {
    REAL rFactor;
  };
  // METHOD M : INT                          -- not virtual: FB_Derived's M hides it
  INT M(args<M_vars> in) { return in.x; }
  // METHOD N : INT
  virtual INT N(args<M_vars> in) { return in.x; }
  // METHOD Scale : REAL
  virtual REAL Scale(args<Scale_vars> in) { return in.rFactor; }
  // METHOD Describe : INT                   -- not virtual, and const
  INT Describe() const { return nCount; }
  virtual void body() {}
};

// FUNCTION_BLOCK FB_Derived EXTENDS FB_Base
struct FB_Derived : extends<FB_Derived, FB_Base> {
  struct Scale2_vars {
    LREAL lrFactor;
  };
  INT M(args<M_vars> in) { return in.x + 1; }                       // hides FB_Base::M
  INT N(args<M_vars> in) override { return in.x + 2; }              // overrides
  REAL Scale(args<Scale2_vars> in) { return REAL(in.lrFactor); }   // other parameters: hides
  void body() override {}
};

// FUNCTION_BLOCK FB_Grandchild EXTENDS FB_Derived: Describe is FB_Base's, two levels up.
struct FB_Grandchild : extends<FB_Grandchild, FB_Derived> {
  INT Describe() const { return 7; }                               // hides FB_Base::Describe
  INT N(args<M_vars> in) override { return in.x + 3; }             // overrides FB_Derived::N
  void body() override { SUPER::body(); }
};

// A block derived without extends<> is a block all the same.
struct FB_Plain : FB_Base {
  INT M(args<M_vars> in) { return in.x * 2; }                       // hides FB_Base::M
};

// A method whose name begins with "operator" is a method like any other.
struct FB_Panel : function_block<FB_Panel> {
  BOOL operatorLogin() { return TRUE; }
  virtual void body() {}
};
struct FB_TouchPanel : extends<FB_TouchPanel, FB_Panel> {
  BOOL operatorLogin() { return FALSE; }                             // hides FB_Panel::operatorLogin
  void body() override {}
};
