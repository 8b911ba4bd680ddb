// Seed: "面向对象的方法" (Chinese OOP page), "相关案例" (the worked case) — the tests of INTERFACE
// I_Math, FB_MathMen, FB_MethErase and PROGRAM MAIN. The POUs, with the seed's ST beside them,
// are in i_math_interface.hpp, which the firmware example embedded/examples/i_math_interface.cpp
// runs on a Cortex-M as well.
#include <iecoop/testing.hpp>

#include "i_math_interface.hpp"

using namespace iecoop;
using seed_i_math::FB_MathMen;
using seed_i_math::FB_MethErase;
using seed_i_math::I_Math;
using seed_i_math::MAIN;

TEST_SUITE("seed: I_Math, FB_MathMen, FB_MethErase and MAIN") {
  TEST_CASE("MAIN through the interface to FB_MathMen: the result is kept") {
    MAIN main;
    main.bUseMemInstance = TRUE;
    main();
    CHECK(main.ipInterface.get() == static_cast<I_Math*>(&main.fbMemInstance));
    CHECK(main.AddResult == 5.0f);           // 2 + 3
    CHECK(main.rResultInterface == 15.0f);   // (2 + 3) * 3
    CHECK(main.fbMemInstance.rMem == 15.0f);
  }

  TEST_CASE("MAIN through the interface to FB_MethErase: each method starts from nothing") {
    MAIN main;
    main.bUseMemInstance = FALSE;
    main();
    CHECK(main.ipInterface.get() == static_cast<I_Math*>(&main.fbEraseInstance));
    CHECK(main.AddResult == 5.0f);          // 2 + 3, then erased
    CHECK(main.rResultInterface == 0.0f);   // 0 * 3
    CHECK(main.fbMemInstance.rMem == 0.0f); // the other block untouched
  }

  TEST_CASE("switching at run time, cycle by cycle") {
    MAIN main;
    testing::cycles run{main};
    for (int cycle = 0; cycle < 4; ++cycle) {
      main.bUseMemInstance = BOOL(cycle % 2 == 0);
      run.step();
      CHECK(main.rResultInterface == (cycle % 2 == 0 ? 15.0f : 0.0f));
    }
    // The interface variable is an input of MAIN, so a caller may also assign it by name.
    FB_MathMen other;
    MAIN::instance()("ipInterface"_ = itf<I_Math>(other));
    CHECK(main.ipInterface.get() != static_cast<I_Math*>(&other));  // MAIN's body re-points it
    CHECK(main.AddResult == 5.0f);
  }
}
