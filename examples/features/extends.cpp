// One feature: EXTENDS. The derived block states its body (SUPER^() runs the base's), its
// methods override the base's virtually, as CODESYS dispatches every method, and it can be
// used wherever the base is expected.
#include <fmt/core.h>

#include <iecoop/fmt.hpp>
#include <iecoop/iecoop.hpp>

using namespace iecoop;

// FUNCTION_BLOCK FB_Axis
struct FB_Axis : function_block<FB_Axis> {
  DINT diTarget;    // VAR_INPUT diTarget : DINT; END_VAR
  DINT diPosition;  // VAR_OUTPUT diPosition : DINT; END_VAR
  using VAR_INPUT = pins<&FB_Axis::diTarget>;
  using VAR_OUTPUT = pins<&FB_Axis::diPosition>;

  virtual void body() {
    diPosition = diPosition + Step();  // diPosition := diPosition + THIS^.Step();
  }
  // METHOD Step : DINT
  virtual DINT Step() {
    DINT Step;                      // the return variable, 0
    if (diTarget > diPosition) {    // IF diTarget > diPosition THEN Step := 1;
      Step = 1;
    } else if (diTarget < diPosition) {  // ELSIF diTarget < diPosition THEN Step := -1;
      Step = -1;
    }                               // END_IF
    return Step;
  }
  // METHOD Describe : STRING
  virtual STRING<> Describe() { return "axis"; }
};

// FUNCTION_BLOCK FB_FastAxis EXTENDS FB_Axis
struct FB_FastAxis : extends<FB_FastAxis, FB_Axis> {
  UINT uiMoves;  // VAR_OUTPUT uiMoves : UINT; END_VAR
  using VAR_OUTPUT = pins<&FB_FastAxis::uiMoves>;  // only what FB_FastAxis adds

  void body() override {
    SUPER::body();           // SUPER^();
    uiMoves = uiMoves + 1;   // uiMoves := uiMoves + 1;
  }
  DINT Step() override {     // METHOD Step : DINT
    return SUPER::Step() * 10;  // Step := SUPER^.Step() * 10;
  }
  STRING<> Describe() override {  // METHOD Describe : STRING
    return CONCAT("fast ", SUPER::Describe());  // Describe := CONCAT('fast ', SUPER^.Describe());
  }
};

// VAR_IN_OUT axis : FB_Axis;  a base reference takes either block
void move(FB_Axis& axis, int calls) {
  for (int i = 0; i < calls; ++i) {
    axis("diTarget"_ = 25);  // axis(diTarget := 25);
  }
  fmt::print("{:<10} position {}\n", axis.Describe(), axis.diPosition);
}

int main() {
  FB_Axis fbAxis;          // fbAxis : FB_Axis;
  FB_FastAxis fbFastAxis;  // fbFastAxis : FB_FastAxis;
  move(fbAxis, 3);
  move(fbFastAxis, 3);  // the base's body, then 10 per step: 30
  fmt::print("fast axis moves {}\n", fbFastAxis.uiMoves);
}
