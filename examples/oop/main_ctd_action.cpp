// Seed: "CoDeSys一些基本概念" (Chinese concepts page), 相关案例 (related example) — PROGRAM MAIN with
// a CTD instance and the action ACT_Action:
//
//   PROGRAM MAIN
//   VAR
//     Inst : CTD;  //CTD的使用,必须先将 load的值置 0-1-0的过程，才能启动减计数。
//                  // (using CTD: LOAD must first go 0-1-0 before counting down can start)
//     In: BOOL;
//     Erg: BOOL;
//     A:INT:=5;
//     B:INT:=10;
//     C:INT;
//   END_VAR
//
//   ACTION ACT_Action:
//   IF IN THEN
//     C:=A+B;
//
// The seed shows MAIN's body only as a picture. Filled in the obvious way: MAIN counts the
// rising edges of In down from a preset of 3 and reports the end in Erg, then calls the
// action. LOAD is the one input the body does not assign: as in the seed, the engineer
// writes it online (here: the test), 0-1-0, before counting starts. The seed's END_IF is
// missing; ST needs it.
#include <iecoop/testing.hpp>

namespace seed_main_ctd_action {

using namespace iecoop;

// PROGRAM MAIN
struct MAIN : program<MAIN> {
  // VAR
  CTD Inst;          // Inst : CTD;
  BOOL In;           // In : BOOL;   (written online, like Inst.LOAD)
  var<BOOL> Erg;     // Erg : BOOL;
  var<INT> A{5};     // A : INT := 5;
  var<INT> B{10};    // B : INT := 10;
  var<INT> C;        // C : INT;
  // END_VAR

  void body() {
    Inst("CD"_ = In, "PV"_ = 3, "Q"_ >> Erg);  // Inst(CD := In, PV := 3, Q => Erg);
    ACT_Action();                                     // ACT_Action();
  }

  // ACTION ACT_Action
  void ACT_Action() {
    if (In) {       // IF IN THEN
      C = A + B;    //     C := A + B;
    }               // END_IF
  }
};

}  // namespace seed_main_ctd_action

using namespace iecoop;
using seed_main_ctd_action::MAIN;

TEST_SUITE("seed: MAIN with CTD Inst and ACT_Action") {
  TEST_CASE("CTD counts down only after LOAD went 0-1-0, the action adds A and B while In is TRUE") {
    MAIN main;
    testing::cycles run{main};
    run.step();
    CHECK(main.Inst.CV == 0);
    CHECK(main.Erg == TRUE);  // CV = 0 before anything is loaded: Q is already TRUE
    CHECK(main.C == 0);

    // Counting before LOAD: CV stays at 0 (a WORD counter does not go below 0).
    main.In = TRUE;
    run.step();
    CHECK(main.Inst.CV == 0);
    CHECK(main.C == 15);  // ACT_Action ran with In TRUE: C := 5 + 10
    main.In = FALSE;
    run.step();

    // LOAD 0-1-0, written online.
    main.Inst.LOAD = TRUE;
    run.step();
    CHECK(main.Inst.CV == 3);
    CHECK(main.Erg == FALSE);
    main.Inst.LOAD = FALSE;
    run.step();

    // Now each rising edge of In counts down; Erg once CV reaches 0.
    for (int edge = 1; edge <= 3; ++edge) {
      run.pulse(main.In);  // one cycle with In TRUE
      CHECK(main.Inst.CV == 3 - edge);
      CHECK(main.Erg == BOOL(edge == 3));
      run.step();  // and one with In FALSE
    }
  }

  TEST_CASE("LOAD held TRUE keeps CV at PV: edges of In are not counted") {
    MAIN main;
    testing::cycles run{main};
    main.Inst.LOAD = TRUE;
    CHECK(testing::run_diagram(run, testing::drive("In", main.In, "#_#_")));  // two rising edges, one cycle each
    CHECK(main.Inst.CV == 3);
    CHECK(main.Erg == FALSE);
  }

  TEST_CASE("the action alone, called from outside: C := A + B only while In is TRUE") {
    MAIN main;
    main.ACT_Action();
    CHECK(main.C == 0);
    main.In = TRUE;
    main.ACT_Action();  // ST: MAIN.ACT_Action();
    CHECK(main.C == 15);
  }
}
