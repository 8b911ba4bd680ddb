// iecoop-check fixture: blocks from a library included as a system header (vendor/, given with
// -isystem) are not checked; the user's code that uses them cleanly is clean.
#include <vendor_blocks.hpp>

using namespace iecoop;

// FUNCTION_BLOCK FB_Mine EXTENDS FB_VendorDerived
struct FB_Mine : extends<FB_Mine, vendor::FB_VendorDerived> {
  var<INT> nMine;
  void body() override {
    SUPER::body();
    nMine = nMine + 1;
  }
};

inline INT Observe(FB_Mine& fb) {
  vendor::vendor_reset(fb);
  return fb.nMine + fb.Peek();
}
