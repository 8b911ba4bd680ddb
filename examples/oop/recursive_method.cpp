// Seed: CODESYS "Object 'Method'" — recursive method call: "Within the implementation, a
// method can call itself, either directly by means of the THIS pointer, or by means of a
// local variable for the assigned function block." (Only the method name, without THIS^ or
// an instance, is an error in CODESYS; in C++ it would compile, so write this-> as ST
// writes THIS^.)
//
// The seed shows the two forms without a body; we use the classic one, the factorial.
#include <doctest/doctest.h>

#include <iecoop/iecoop.hpp>
#include <iecoop/ostream.hpp>

namespace seed_recursive_method {

using namespace iecoop;

// FUNCTION_BLOCK FB_Math
struct FB_Math : function_block<FB_Math> {

  // {attribute 'estimated-stack-usage' := '99'}
  // METHOD Fact : DINT
  // VAR_INPUT n : DINT; END_VAR
  struct Fact_vars {
    DINT n;
  };
  DINT Fact(args<Fact_vars> in) {
    if (in.n <= 1) return 1;                   // IF n <= 1 THEN Fact := 1;
    return in.n * this->Fact(in.n - 1);  // ELSE Fact := n * THIS^.Fact(n - 1); END_IF
  }

  // METHOD Fib : DINT                  (recursion through a local instance of the block)
  // VAR_INPUT n : DINT; END_VAR
  // VAR fb_Temp : FB_Math; END_VAR
  struct Fib_vars {
    DINT n;
  };
  DINT Fib(args<Fib_vars> in) {
    FB_Math fb_Temp;  // a method's locals are new on every call
    if (in.n < 2) return in.n;  // IF n < 2 THEN Fib := n;
    return fb_Temp.Fib(in.n - 1) + fb_Temp.Fib(in.n - 2);  // ELSE Fib := fb_Temp.Fib(n - 1) + fb_Temp.Fib(n - 2); END_IF
  }
};

}  // namespace seed_recursive_method

using namespace iecoop;
using seed_recursive_method::FB_Math;

TEST_SUITE("seed: recursive method") {
  TEST_CASE("a method calls itself through THIS^") {
    FB_Math math;
    CHECK(math.Fact(1) == 1);
    CHECK(math.Fact(5) == 120);
    CHECK(math.Fact({"n"_ = 10}) == 3628800);
    CHECK(math.Fact(13) == 1932053504);  // 13! = 6227020800 wraps in DINT, as on a PLC
  }

  TEST_CASE("a method calls itself through a local instance of its block") {
    FB_Math math;
    CHECK(math.Fib(0) == 0);
    CHECK(math.Fib(1) == 1);
    CHECK(math.Fib(20) == 6765);
  }
}
