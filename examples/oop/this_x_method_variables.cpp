// Seed: "CoDeSys一些基本概念" (Chinese concepts page), methods — "您可以使用标识符“THIS”来直接引用
// 默认的功能块实例。... 所以上例中的语句“THIS^.x”,并不是功能块内方法的输入参数x,而是功能块的局部变
// 量x。" (THIS refers to the block's own instance; the statement THIS^.x is not the method's
// input x but the block's variable x.) The CODESYS method pages in the seeds add: "The THIS
// pointer allows for access to its own function block instance."
//
// The "above example" the seed refers to is not in it. We complete it minimally: FB_X has a
// VAR x, and its methods have an input x (SetX, AddX) or a VAR x (ExchangeX) of the same name.
// The sentence before, "如果功能块内有和方法中同名的局部变量,那么引用这个变量名时会优先使用功能块内
// 的局部变量", reads as if the block's variable won; CODESYS's rule (and the seed's own
// conclusion) is the other way round: inside a method the plain name is the method's variable,
// and THIS^.x is the block's ("Shadowing Rules": the method's own declarations are searched
// first).
//
// C++: a method's inputs are `in.x` (its args<Vars> parameter), so they shadow nothing and the
// block's x is `x` or, written as ST writes THIS^.x, `this->x`. Beware the one place where the
// two languages differ: a plain `x` in a method with an input x is the input in ST but the
// block's x in C++. Write `in.x` for every plain x of the ST.
//
// A method's VAR is declared with its inputs, as temp<T> in the same struct: `in.x` too, so a
// method's own names are all `in.` + the name and nothing shadows the block's (a C++ local named
// like a member would, and -Wshadow says so).
#include <doctest/doctest.h>

#include <iecoop/iecoop.hpp>
#include <iecoop/ostream.hpp>

namespace seed_this_x {

using namespace iecoop;

// FUNCTION_BLOCK FB_X
struct FB_X : function_block<FB_X> {
  // VAR
  var<INT> x;  // x : INT;      (the block's x)
  // END_VAR

  // METHOD SetX
  // VAR_INPUT
  //     x : INT;               (the method's input x)
  // END_VAR
  struct SetX_vars {
    INT x;
  };
  void SetX(args<SetX_vars> in) {
    this->x = in.x;  // THIS^.x := x;     the block's x := the input x
  }

  // METHOD AddX : INT
  // VAR_INPUT
  //     x : INT;
  // END_VAR
  struct AddX_vars {
    INT x;
  };
  INT AddX(args<AddX_vars> in) {
    return this->x + in.x;  // AddX := THIS^.x + x;     the block's x plus the input x
  }

  // METHOD ExchangeX : INT
  // VAR_INPUT
  //     iNew : INT;
  // END_VAR
  // VAR
  //     x : INT;               (the method's own x, new on every call)
  // END_VAR
  struct ExchangeX_vars {
    INT iNew;
    temp<INT> x;
  };
  INT ExchangeX(args<ExchangeX_vars> in) {
    in.x = this->x;      // x := THIS^.x;          the method's x := the block's x
    this->x = in.iNew;   // THIS^.x := iNew;       the block's x := the new value
    return in.x;         // ExchangeX := x;        the method's x: the old value
  }
};

}  // namespace seed_this_x

using namespace iecoop;
using seed_this_x::FB_X;

TEST_SUITE("seed: THIS^.x against a method variable x") {
  TEST_CASE("THIS^.x := x writes the block's x from the method's input x") {
    FB_X fb;
    CHECK(fb.x == 0);
    fb.SetX(5);  // fb.SetX(x := 5);
    CHECK(fb.x == 5);
    fb.SetX({"x"_ = -3});
    CHECK(fb.x == -3);
  }

  TEST_CASE("THIS^.x + x adds the block's x and the input x, and leaves the block's x alone") {
    FB_X fb;
    fb.SetX(10);
    CHECK(fb.AddX(1) == 11);
    CHECK(fb.AddX({"x"_ = 100}) == 110);
    CHECK(fb.x == 10);
    fb.SetX(0);
    CHECK(fb.AddX(7) == 7);  // had the port added the block's x twice, this would be 0
  }

  TEST_CASE("a method's VAR x is not the block's x: ExchangeX returns the old value and keeps the new") {
    FB_X fb;
    fb.SetX(1);
    CHECK(fb.ExchangeX(2) == 1);
    CHECK(fb.x == 2);
    CHECK(fb.ExchangeX({"iNew"_ = 3}) == 2);
    CHECK(fb.x == 3);
    // Two instances: THIS^ is the instance the method was called on.
    FB_X other;
    CHECK(other.ExchangeX(9) == 0);
    CHECK(other.x == 9);
    CHECK(fb.x == 3);
  }
}
