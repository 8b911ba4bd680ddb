// Seed: CODESYS "Object 'Method'" (English, Chinese and German pages) — the method DoIt,
// called with named arguments in any order, positionally, and with inputs left out.
//
// The seed shows only the method. Around it we put the obvious block, FB_DoIt, which keeps
// the text of the last call (sLastText) so that a test can see STRING(12) truncate it.
//
// The POUs are in this header so that one source serves the host's tests (method_doit.cpp) and
// the firmware example embedded/examples/property_and_method.cpp.
#pragma once

#include <iecoop/iecoop.hpp>

namespace seed_method_doit {

using namespace iecoop;

// FUNCTION_BLOCK FB_DoIt
struct FB_DoIt : function_block<FB_DoIt> {
  // VAR
  //   sLastText : STRING(12);          (our addition, to observe sInput_3)
  // END_VAR
  var<STRING<12>> sLastText;

  // METHOD PUBLIC DoIt : BOOL
  // VAR_INPUT
  //     iInput_1 : DWORD;
  //     iInput_2 : DWORD;
  //     sInput_3 : STRING(12);
  // END_VAR
  struct DoIt_vars {
    DWORD iInput_1;
    DWORD iInput_2;
    STRING<12> sInput_3;
  };
  BOOL DoIt(args<DoIt_vars> in) {
    sLastText = in.sInput_3;        // sLastText := sInput_3;   (our addition)
    if (in.iInput_1 == in.iInput_2) {  // IF iInput_1 = iInput_2 THEN
      return TRUE;                     //     DoIt := TRUE; // explicit return value
    }                                  // END_IF
    return FALSE;                      // (DoIt starts each call at FALSE)
  }

  // The German page's optional parameter: an input with an initial value may be left out.
  // METHOD PUBLIC DoItWithDefault : BOOL
  // VAR_INPUT
  //     iInput_1 : DWORD;
  //     iInput_2 : DWORD := 16#10;
  // END_VAR
  struct DoItWithDefault_vars {
    DWORD iInput_1;
    DWORD iInput_2 = 0x10;
  };
  BOOL DoItWithDefault(args<DoItWithDefault_vars> in) { return in.iInput_1 == in.iInput_2; }
};

}  // namespace seed_method_doit
