// Seed: CODESYS "Object 'Interface'" and "Command 'Implement interfaces'" (English page) —
// the interface ITF with the methods Method1 and Method2, which hold declarations only, and a
// function block that implements it and supplies the code: "FUNCTION_BLOCK POU_Im
// IMPLEMENTS ITF1" (the dialog walkthrough calls the interface ITF1; here it is ITF).
//
// The seed does not give the methods' variables or code. We give Method1 a BOOL input and
// Method2 an INT input and an extra output, and POU_Im obvious bodies: Method1 switches the
// block on or off, Method2 adds to a total while the block is on.
#include <doctest/doctest.h>

#include <iecoop/iecoop.hpp>
#include <iecoop/ostream.hpp>

namespace seed_itf {

using namespace iecoop;

// INTERFACE ITF
struct ITF : interface_base<ITF> {
  // METHOD Method1 : BOOL
  // VAR_INPUT
  //     bOn : BOOL;
  // END_VAR
  struct Method1_vars {
    BOOL bOn;
  };
  virtual BOOL Method1(args<Method1_vars> in) = 0;

  // METHOD Method2 : INT
  // VAR_INPUT
  //     iAdd : INT;
  // END_VAR
  // VAR_OUTPUT
  //     bCounted : BOOL;
  // END_VAR
  struct Method2_vars {
    INT iAdd;
    output<BOOL> bCounted;
  };
  virtual INT Method2(args<Method2_vars> in) = 0;
};
using ITF1 = ITF;  // the name the seed's dialog walkthrough uses

// FUNCTION_BLOCK POU_Im IMPLEMENTS ITF1
struct POU_Im : function_block<POU_Im, implements<ITF1>> {
  // VAR bOn : BOOL; iTotal : INT; END_VAR
  var<BOOL> bOn;
  var<INT> iTotal;

  // METHOD Method1 : BOOL          (code ours; its input bOn shadows the block's bOn)
  BOOL Method1(args<Method1_vars> in) override {
    BOOL Method1 = this->bOn;  // Method1 := THIS^.bOn;   (the previous state)
    this->bOn = in.bOn;        // THIS^.bOn := bOn;       (the method's input)
    return Method1;
  }
  // METHOD Method2 : INT           (code ours)
  INT Method2(args<Method2_vars> in) override {
    if (bOn) {                       // IF bOn THEN
      iTotal = iTotal + in.iAdd;     //     iTotal := iTotal + iAdd;
    }                                // END_IF
    in.bCounted = bOn;               // bCounted := bOn;
    return iTotal;                   // Method2 := iTotal;
  }
};

}  // namespace seed_itf

using namespace iecoop;
using seed_itf::ITF;
using seed_itf::POU_Im;

TEST_SUITE("seed: ITF with Method1 and Method2, POU_Im IMPLEMENTS ITF1") {
  TEST_CASE("the block's code runs when the interface's methods are called") {
    POU_Im pou;
    itf<ITF> ip = pou;
    BOOL bCounted;
    CHECK(ip->Method2({"iAdd"_ = 5, "bCounted"_ >> bCounted}) == 0);  // off: nothing added
    CHECK(bCounted == FALSE);
    CHECK(ip->Method1(TRUE) == FALSE);  // was off
    CHECK(ip->Method2({"iAdd"_ = 5, "bCounted"_ >> bCounted}) == 5);
    CHECK(bCounted == TRUE);
    CHECK(ip->Method2({7}) == 12);
    CHECK(pou.iTotal == 12);
  }

  TEST_CASE("POU_Im provides every method of ITF") {
    static_assert(Implements<POU_Im, ITF>);
    static_assert(std::is_abstract_v<ITF>);
  }
}
