// One feature: an ACTION. It is code on its block's variables, without declarations of its
// own: a member function without parameters, called on the instance like the block.
#include <fmt/core.h>

#include <iecoop/fmt.hpp>
#include <iecoop/iecoop.hpp>

using namespace iecoop;

// FUNCTION_BLOCK FB_Counter
struct FB_Counter : function_block<FB_Counter> {
  BOOL bCount;     // VAR_INPUT bCount : BOOL; END_VAR
  UINT uiValue;    // VAR_OUTPUT uiValue : UINT;
  UINT uiResets;   //            uiResets : UINT; END_VAR
  using VAR_INPUT = pins<&FB_Counter::bCount>;
  using VAR_OUTPUT = pins<&FB_Counter::uiValue, &FB_Counter::uiResets>;

  void body() {
    if (bCount) {               // IF bCount THEN
      uiValue = uiValue + 1;    //     uiValue := uiValue + 1;
    }                           // END_IF
    if (uiValue >= 3) {         // IF uiValue >= 3 THEN
      Reset();                  //     Reset();        the action, from the block's own code
    }                           // END_IF
  }

  // ACTION Reset:
  void Reset() {
    uiValue = 0;               // uiValue := 0;
    uiResets = uiResets + 1;   // uiResets := uiResets + 1;
  }
};

int main() {
  FB_Counter fbCounter;  // fbCounter : FB_Counter;
  for (int i = 0; i < 4; ++i) {
    fbCounter("bCount"_ = TRUE);  // fbCounter(bCount := TRUE);
    fmt::print("call:             value {}  resets {}\n", fbCounter.uiValue, fbCounter.uiResets);
  }
  fbCounter.Reset();  // fbCounter.Reset();      the action, from outside
  fmt::print("Reset():          value {}  resets {}\n", fbCounter.uiValue, fbCounter.uiResets);
  // fbCounter.Reset(bCount := FALSE);     the inputs assigned first, then the action
  fbCounter.with("bCount"_ = FALSE).Reset();
  fmt::print("Reset(bCount:=0): value {}  resets {}  bCount {}\n", fbCounter.uiValue, fbCounter.uiResets,
             fbCounter.bCount);
}
