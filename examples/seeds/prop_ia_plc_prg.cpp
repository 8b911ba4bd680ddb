// Seed: CODESYS "Object 'Property'" (English page), the example — FUNCTION_BLOCK FB_A with
// the property prop_iA, and PLC_PRG, which calls the block, resets the property when it
// passes 500 and reads it into iVar. Complete in the seed; the tests are ours.
#include <doctest/doctest.h>

#include <iecoop/iecoop.hpp>
#include <iecoop/ostream.hpp>

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
  [[no_unique_address]] property<INT, &FB_A::prop_iA_Get, &FB_A::prop_iA_Set> prop_iA;
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

using namespace iecoop;
using seed_prop_ia::FB_A;
using seed_prop_ia::PLC_PRG;

TEST_SUITE("seed: FB_A.prop_iA and PLC_PRG") {
  TEST_CASE("iVar counts up to 500, then the property resets it to 0") {
    PLC_PRG plc_prg;
    for (int cycle = 1; cycle <= 500; ++cycle) plc_prg();
    CHECK(plc_prg.iVar == 500);
    plc_prg();  // 501 > 500: prop_iA := 0
    CHECK(plc_prg.iVar == 0);
    plc_prg();
    CHECK(plc_prg.iVar == 1);
  }

  TEST_CASE("1,200 cycles: the value wraps to 0 after 500, twice") {
    PLC_PRG plc_prg;
    int wraps = 0;
    for (int cycle = 1; cycle <= 1200; ++cycle) {
      plc_prg();
      if (plc_prg.iVar == 0) ++wraps;
      CHECK(plc_prg.iVar <= 500);
    }
    CHECK(wraps == 2);               // cycles 501 and 1002
    CHECK(plc_prg.iVar == 198);      // 1200 - 2 * 501
    CHECK(plc_prg.fbA.iA == 198);
  }

  TEST_CASE("the property costs FB_A nothing and inlines to its accessors") {
    static_assert(sizeof(FB_A) == sizeof(INT));
    FB_A fbA;
    CHECK(static_cast<void*>(&fbA.prop_iA) == static_cast<void*>(&fbA));
  }
}
