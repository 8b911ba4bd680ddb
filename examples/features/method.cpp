// One feature: a METHOD. Its variables are one struct, reached as in.x; arguments go by name in
// any order or by position; inputs left out take their initial values; the return variable is
// a local named like the method.
#include <fmt/core.h>

#include <iecoop/fmt.hpp>
#include <iecoop/iecoop.hpp>

using namespace iecoop;

// FUNCTION_BLOCK FB_Scale
struct FB_Scale : function_block<FB_Scale> {
  var<DINT> diUsed;  // VAR diUsed : DINT; END_VAR

  // METHOD Scale : DINT
  struct Scale_vars {
    INT iRaw;          // VAR_INPUT iRaw : INT;
    INT iGain = 1;     //           iGain : INT := 1;
    INT iOffset;       //           iOffset : INT; END_VAR
    output<BOOL> bOk;  // VAR_OUTPUT bOk : BOOL; END_VAR
  };
  DINT Scale(args<Scale_vars> in) {
    DINT Scale = in.iRaw * in.iGain + in.iOffset;  // Scale := iRaw * iGain + iOffset;
    in.bOk = in.iRaw >= 0;                         // bOk := iRaw >= 0;
    diUsed = diUsed + 1;                           // diUsed := diUsed + 1;
    return Scale;
  }

  void body() {}
};

int main() {
  FB_Scale fbScale;  // fbScale : FB_Scale;
  DINT diValue;      // diValue : DINT;
  BOOL bOk;          // bOk : BOOL;

  // diValue := fbScale.Scale(iOffset := 5, iRaw := 100, iGain := 3);     named, any order
  diValue = fbScale.Scale({"iOffset"_ = 5, "iRaw"_ = 100, "iGain"_ = 3});
  fmt::print("named:       {}\n", diValue);

  // diValue := fbScale.Scale(100, 3, 5);                                  positional
  diValue = fbScale.Scale({100, 3, 5});
  fmt::print("positional:  {}\n", diValue);

  // diValue := fbScale.Scale(iRaw := 100);                                iGain 1, iOffset 0
  diValue = fbScale.Scale({"iRaw"_ = 100});
  fmt::print("defaults:    {}\n", diValue);

  // diValue := fbScale.Scale(iRaw := -20000, iGain := 4, bOk => bOk);     no INT overflow:
  diValue = fbScale.Scale({"iRaw"_ = -20000, "iGain"_ = 4, "bOk"_ >> bOk});  // DINT result
  fmt::print("output:      {} ok {}\n", diValue, bOk);
  fmt::print("calls:       {}\n", fbScale.diUsed);
}
