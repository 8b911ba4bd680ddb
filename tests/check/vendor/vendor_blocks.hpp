// iecoop-check fixture: a vendor's block library, included as a system header (-isystem).
// It has the slips the checks look for, but they are not the user's to fix: not reported.
#pragma once

#include <iecoop/iecoop.hpp>

namespace vendor {

using namespace iecoop;

struct FB_VendorBase : function_block<FB_VendorBase> {
  var<INT> nState;
  struct Step_vars {
    INT nState;
  };
  INT Step(args<Step_vars> in) { return nState + in.nState; }
  INT Peek() { return nState; }
  virtual void body() {}
};

struct FB_VendorDerived : extends<FB_VendorDerived, FB_VendorBase> {
  var<INT> nState;
  INT Peek() { return 1; }
  void body() override {}
};

inline void vendor_reset(FB_VendorBase& fb) { fb.nState = 0; }

}  // namespace vendor
