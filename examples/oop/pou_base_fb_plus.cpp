// Seed: "面向对象的方法" (Chinese OOP page), the inheritance example — POU_Base and
// FB_Plus EXTENDS POU_Base, which calls methods through THIS^ and SUPER^.
//
// The seed leaves out the bodies of POU_Base's methods M_DoIt and M_DoAlso and of FB_Plus's
// override of M_DoIt. We fill them in the obvious way: each counts in iCntBase and leaves
// its name in iMessageBase, so a test sees which implementation ran. (The seed spells the
// method "M_Dolt" and the BOOL "Ruslt"; we keep its names.)
#include <doctest/doctest.h>

#include <iecoop/iecoop.hpp>
#include <iecoop/ostream.hpp>

namespace seed_pou_base {

using namespace iecoop;

// FUNCTION_BLOCK POU_Base
struct POU_Base : function_block<POU_Base> {
  virtual ~POU_Base() = default;
  virtual void body() {}

  // METHOD M_Dolt                   (body not in the seed: count by 1, say who ran)
  virtual void M_Dolt() {
    iCntBase = iCntBase + 1;
    iMessageBase = "POU_Base.M_Dolt";
  }
  // METHOD M_DoAlso                 (body not in the seed)
  virtual void M_DoAlso() { iMessageBase = "POU_Base.M_DoAlso"; }

 protected:
  // VAR
  //   iCntBase : INT;
  //   iMessageBase : STRING;
  // END_VAR
  // (protected: FB_Plus, derived from POU_Base, writes them too)
  INT iCntBase;
  STRING<> iMessageBase;
};

// FUNCTION_BLOCK FB_Plus EXTENDS POU_Base
struct FB_Plus : extends<FB_Plus, POU_Base> {
  // VAR_INPUT
  BOOL Blocal_1;
  BOOL Blocal_2;
  // VAR_OUTPUT
  INT icnt;
  STRING<> sMessage;
  // VAR
  var<BOOL> Ruslt;

  using VAR_INPUT = pins<&FB_Plus::Blocal_1, &FB_Plus::Blocal_2>;
  using VAR_OUTPUT = pins<&FB_Plus::icnt, &FB_Plus::sMessage>;

  // METHOD M_Dolt                   (FB_Plus's override; body not in the seed)
  void M_Dolt() override {
    iCntBase = iCntBase + 10;
    iMessageBase = "FB_Plus.M_Dolt";
  }

  void body() override {
    if (Blocal_1) {                          // IF Blocal_1 THEN
      this->M_Dolt();                        //     THIS^.M_Dolt();        // the derived method
      icnt = this->iCntBase;                 //     icnt := THIS^.iCntBase;
      sMessage = this->iMessageBase;         //     sMessage := THIS^.iMessageBase;
    } else if (Blocal_2 && !Blocal_1) {      // ELSIF Blocal_2 AND NOT Blocal_1 THEN
      SUPER::M_DoAlso();                     //     SUPER^.M_DoAlso();     // the base method
      Ruslt = TRUE;                          //     Ruslt := TRUE;
    } else {                                 // ELSE
      SUPER::M_Dolt();                       //     SUPER^.M_Dolt();       // the base method
      icnt = SUPER::iCntBase;                //     icnt := SUPER^.iCntBase;
      sMessage = SUPER::iMessageBase;        //     sMessage := SUPER^.iMessageBase;
    }                                        // END_IF
  }
};

}  // namespace seed_pou_base

using namespace iecoop;
using seed_pou_base::FB_Plus;
using seed_pou_base::POU_Base;

TEST_SUITE("seed: POU_Base and FB_Plus (THIS^, SUPER^)") {
  TEST_CASE("THIS^.M_Dolt() runs the most derived override") {
    FB_Plus fb;
    fb("Blocal_1"_ = TRUE);
    CHECK(fb.icnt == 10);
    CHECK(fb.sMessage == "FB_Plus.M_Dolt");
    CHECK(fb.Ruslt == FALSE);
  }

  TEST_CASE("SUPER^.M_Dolt() runs the base implementation") {
    FB_Plus fb;
    fb();  // neither input set: the ELSE branch
    CHECK(fb.icnt == 1);
    CHECK(fb.sMessage == "POU_Base.M_Dolt");
    fb("Blocal_1"_ = TRUE);  // THIS^ adds 10 to the same counter
    CHECK(fb.icnt == 11);
  }

  TEST_CASE("SUPER^.M_DoAlso() and the block's own local") {
    FB_Plus fb;
    fb("Blocal_2"_ = TRUE);
    CHECK(fb.Ruslt == TRUE);
    CHECK(fb.icnt == 0);  // outputs untouched on this branch
  }

  TEST_CASE("an FB_Plus is a POU_Base: calls through the base reach the overrides") {
    FB_Plus fb;
    POU_Base& base = fb;
    base.M_Dolt();  // virtual: FB_Plus's M_Dolt
    fb("Blocal_1"_ = FALSE, "Blocal_2"_ = FALSE);  // SUPER^.M_Dolt: +1
    CHECK(fb.icnt == 11);
    fb.Blocal_1 = TRUE;
    base();  // calling through the base runs FB_Plus's body
    CHECK(fb.icnt == 21);
    CHECK(fb.sMessage == "FB_Plus.M_Dolt");
  }
}
