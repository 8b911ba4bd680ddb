// One feature: an ABSTRACT block without a body of its own, marked no_explicit_call and
// no_assign as in TwinCAT, extended by two blocks with their own bodies. Calling a derived
// block runs its body; SUPER^() runs the base's empty one; the methods dispatch to the most
// derived override, also through a reference to the base.
#include <fmt/core.h>

#include <iecoop/fmt.hpp>
#include <iecoop/iecoop.hpp>

using namespace iecoop;

// {attribute 'no_explicit_call' := 'use the derived blocks'}
// {attribute 'no_assign'}
// FUNCTION_BLOCK ABSTRACT FB_Limit
struct FB_Limit : function_block<FB_Limit, attributes<no_explicit_call, no_assign>> {
  REAL fIn;         // VAR_INPUT fIn : REAL; END_VAR
  REAL fOut;        // VAR_OUTPUT fOut : REAL; END_VAR
  var<UINT> nHits;  // VAR nHits : UINT; END_VAR
  using VAR_INPUT = pins<&FB_Limit::fIn>;
  using VAR_OUTPUT = pins<&FB_Limit::fOut>;

  virtual REAL Apply(REAL fValue) = 0;  // METHOD ABSTRACT Apply : REAL
  // METHOD Run   fOut := THIS^.Apply(fIn); IF fOut <> fIn THEN nHits := nHits + 1; END_IF
  void Run() {
    fOut = Apply(fIn);
    if (fOut != fIn) nHits = nHits + 1;
  }
  virtual ~FB_Limit() = default;

 protected:
  FB_Limit() = default;
};  // (no implementation)

// FUNCTION_BLOCK FB_Clamp EXTENDS FB_Limit
struct FB_Clamp : extends<FB_Clamp, FB_Limit> {
  REAL fMaximum = 10.0F;  // VAR_INPUT fMaximum : REAL := 10; END_VAR
  using VAR_INPUT = pins<&FB_Clamp::fMaximum>;

  REAL Apply(REAL fValue) override { return MIN(fValue, fMaximum); }  // METHOD Apply
  void body() override {
    SUPER::body();  // SUPER^();  FB_Limit's implementation: empty
    Run();          // Run();
  }
};

// FUNCTION_BLOCK FB_DeadBand EXTENDS FB_Limit
struct FB_DeadBand : extends<FB_DeadBand, FB_Limit> {
  REAL Apply(REAL fValue) override {  // METHOD Apply
    return ABS(fValue) < REAL(1.0F) ? REAL(0.0F) : fValue;
  }
  void body() override { Run(); }  // Run();
};

// VAR_IN_OUT limit : FB_Limit;  the methods dispatch to the derived block's
void show(const char* name, FB_Limit& limit) {
  fmt::print("{:<9} Apply(12.5) = {}, hits {}\n", name, limit.Apply(12.5F), limit.nHits);
}

int main() {
  FB_Clamp fbClamp;        // fbClamp : FB_Clamp;
  FB_DeadBand fbDeadBand;  // fbDeadBand : FB_DeadBand;
  for (REAL fIn : {REAL(0.5F), REAL(5.0F), REAL(15.0F)}) {
    fbClamp("fIn"_ = fIn);     // fbClamp(fIn := fIn);
    fbDeadBand("fIn"_ = fIn);  // fbDeadBand(fIn := fIn);
    fmt::print("in {:>4}: clamp {:>4}, dead band {:>4}\n", fIn, fbClamp.fOut, fbDeadBand.fOut);
  }
  show("clamp", fbClamp);
  show("dead band", fbDeadBand);
  // fbClamp2 := fbClamp; (no_assign) and a call of an FB_Limit (no_explicit_call) do not compile.
}
