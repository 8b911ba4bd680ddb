// Seed: "CoDeSys一些基本概念" (Chinese concepts page), extension of function blocks —
// FUNCTION_BLOCK fbB EXTENDS fbA: fbB has all of fbA's variables and methods, can be used
// wherever an fbA is expected, may override fbA's methods, reaches fbA's through SUPER^,
// and may not declare a variable that fbA already has (a compile error, also in iecoop:
// see tests/compile_fail/extends_duplicate_pin.cpp).
//
// The seed shows only the declarations ("...."). We give fbA a body that scales x and a
// method Describe, and fbB an override of Describe that uses SUPER^.
#include <doctest/doctest.h>

#include <iecoop/iecoop.hpp>
#include <iecoop/ostream.hpp>

namespace seed_fba_fbb {

using namespace iecoop;

// FUNCTION_BLOCK fbA
struct fbA : function_block<fbA> {
  virtual ~fbA() = default;
  // VAR_INPUT
  //   x : INT;
  // END_VAR
  INT x;
  // VAR_OUTPUT
  //   y : INT;           (our addition)
  // END_VAR
  INT y;
  using VAR_INPUT = pins<&fbA::x>;
  using VAR_OUTPUT = pins<&fbA::y>;

  virtual void body() { y = x * 2; }           // y := x * 2;

  // METHOD Describe : STRING
  virtual STRING<> Describe() { return "fbA"; }  // Describe := 'fbA';
};

// FUNCTION_BLOCK fbB EXTENDS fbA
struct fbB : extends<fbB, fbA> {
  // VAR_INPUT
  //   ivar : INT;
  // END_VAR
  INT ivar;
  using VAR_INPUT = pins<&fbB::ivar>;  // fbB lists only what it adds

  void body() override {
    SUPER::body();  // SUPER^();          the base body first
    y = y + ivar;   // y := y + ivar;
  }

  // METHOD Describe : STRING          (overrides fbA's: same name, same interface)
  STRING<> Describe() override { return CONCAT(SUPER::Describe(), "/fbB"); }  // CONCAT(SUPER^.Describe(), '/fbB')
};

// FUNCTION Twice : INT  VAR_INPUT fb : fbA; END_VAR (an fbA is expected here)
inline INT Twice(fbA& fb) {
  fb();                 // fb();
  return fb.y * 2;      // Twice := fb.y * 2;
}

}  // namespace seed_fba_fbb

using namespace iecoop;
using seed_fba_fbb::fbA;
using seed_fba_fbb::fbB;

TEST_SUITE("seed: fbB EXTENDS fbA") {
  TEST_CASE("fbB has fbA's variables and its own, and all are callable by name") {
    fbB b;
    INT result;
    b("x"_ = 5, "ivar"_ = 1, "y"_ >> result);  // x is fbA's input, ivar fbB's
    CHECK(result == 11);
    CHECK(b.x == 5);
    static_assert(inputs_of<fbB>::size == 2 && inputs_of<fbB>::names[0] == "x" && inputs_of<fbB>::names[1] == "ivar");
    static_assert(outputs_of<fbB>::size == 1);
  }

  TEST_CASE("an fbB can be used wherever an fbA is expected") {
    fbB b;
    b.x = 3;
    b.ivar = 4;
    CHECK(seed_fba_fbb::Twice(b) == 20);  // fbB's body ran: (3 * 2 + 4) * 2
    fbA a;
    a.x = 3;
    CHECK(seed_fba_fbb::Twice(a) == 12);
  }

  TEST_CASE("fbB overrides fbA's method and reaches the original through SUPER^") {
    fbB b;
    fbA& as_a = b;
    CHECK(as_a.Describe() == "fbA/fbB");
    CHECK(b.fbA::Describe() == "fbA");
  }
}
