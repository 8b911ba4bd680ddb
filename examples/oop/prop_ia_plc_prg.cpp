// Seed: CODESYS "Object 'Property'" (English page) — the tests of FUNCTION_BLOCK FB_A with the
// property prop_iA and of PLC_PRG. The POUs, with the seed's ST beside them, are in
// prop_ia_plc_prg.hpp, which the firmware example embedded/examples/property_and_method.cpp
// runs on a Cortex-M as well.
#include <iecoop/testing.hpp>

#include "prop_ia_plc_prg.hpp"

using namespace iecoop;
using seed_prop_ia::FB_A;
using seed_prop_ia::PLC_PRG;

TEST_SUITE("seed: FB_A.prop_iA and PLC_PRG") {
  TEST_CASE("iVar counts up to 500, then the property resets it to 0") {
    PLC_PRG plc_prg;
    testing::cycles run{plc_prg};
    run.step(500);
    CHECK(plc_prg.iVar == 500);
    run.step();  // 501 > 500: prop_iA := 0
    CHECK(plc_prg.iVar == 0);
    run.step();
    CHECK(plc_prg.iVar == 1);
  }

  TEST_CASE("1,200 cycles: the value wraps to 0 after 500, twice") {
    PLC_PRG plc_prg;
    testing::cycles run{plc_prg};
    int wraps = 0;
    for (int cycle = 1; cycle <= 1200; ++cycle) {
      run.step();
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
