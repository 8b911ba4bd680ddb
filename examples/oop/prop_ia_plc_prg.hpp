// Seed: CODESYS "Object 'Property'" (English page), the example — FUNCTION_BLOCK FB_A with
// the property prop_iA, and PLC_PRG, which calls the block, resets the property when it
// passes 500 and reads it into iVar. Complete in the seed; the tests are ours.
//
// The POUs are in this header so that one source serves the host's tests
// (prop_ia_plc_prg.cpp) and the firmware example embedded/examples/property_and_method.cpp.
#pragma once

#include <iecoop/iecoop.hpp>

namespace seed_prop_ia {

using namespace iecoop;

// FUNCTION_BLOCK FB_A
struct FB_A : function_block<FB_A> {
  // VAR_INPUT
  // END_VAR
  // VAR_OUTPUT
  // END_VAR
  // VAR
  var<INT> iA;  // iA : INT;
  // END_VAR

  void body() {
    iA = iA + 1;  // iA := iA + 1;
  }

  // PROPERTY PUBLIC prop_iA : INT
  // FB_A.prop_iA.Get
  INT prop_iA_Get() { return iA; }  // prop_iA := iA;
  // FB_A.prop_iA.Set
  void prop_iA_Set(INT value) { iA = value; }  // iA := prop_iA;
  [[no_unique_address]] property<INT, &FB_A::prop_iA_Get, &FB_A::prop_iA_Set> prop_iA{this};
};

// PROGRAM PLC_PRG
struct PLC_PRG : program<PLC_PRG> {
  // VAR
  FB_A fbA;        // fbA : FB_A;
  var<INT> iVar;   // iVar : INT;
  // END_VAR

  void body() {
    fbA();                     // fbA();
    if (fbA.prop_iA > 500) {   // IF fbA.prop_iA > 500 THEN
      fbA.prop_iA = 0;         //     fbA.prop_iA := 0;
    }                          // END_IF
    iVar = fbA.prop_iA;        // iVar := fbA.prop_iA;
  }
};

}  // namespace seed_prop_ia
