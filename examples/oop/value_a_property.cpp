// Seed: "属性" (Chinese page on PROPERTY), the example — FUNCTION_BLOCK fb_A with the property
// Value_A, whose Get accessor reads iA and whose Set accessor writes iB; the block's body
// counts iA up. Complete in the seed; the test is ours.
#include <iecoop/testing.hpp>

namespace seed_value_a {

using namespace iecoop;

// FUNCTION_BLOCK fb_A
struct fb_A : function_block<fb_A> {
  // VAR_INPUT
  // END_VAR
  // VAR_OUTPUT
  // END_VAR
  // VAR
  var<INT> iA;  // iA : INT;
  var<INT> iB;  // iB : INT;
  // END_VAR

  void body() {
    iA = iA + 1;  // iA := iA + 1;
  }

  // PROPERTY PUBLIC Value_A : INT
  // fb_A.Value_A.Get
  INT Value_A_Get() { return iA; }  // Value_A := iA;
  // fb_A.Value_A.Set
  void Value_A_Set(INT value) { iB = value; }  // iB := Value_A;
  [[no_unique_address]] property<INT, &fb_A::Value_A_Get, &fb_A::Value_A_Set> Value_A{this};
};

}  // namespace seed_value_a

using namespace iecoop;
using seed_value_a::fb_A;

TEST_SUITE("seed: fb_A.Value_A (Get reads iA, Set writes iB)") {
  TEST_CASE("reading calls Get, writing calls Set, and they reach different variables") {
    fb_A fb;
    testing::cycles run{fb};
    run.step(3);
    CHECK(fb.Value_A == 3);  // Get: iA
    fb.Value_A = 10;         // Set: iB := 10
    CHECK(fb.iB == 10);
    CHECK(fb.iA == 3);
    CHECK(fb.Value_A == 3);  // what was written is not what is read
  }

  TEST_CASE("the property costs fb_A nothing") {
    struct fb_A_data : function_block<fb_A_data> {
      INT iA;
      INT iB;
    };
    static_assert(sizeof(fb_A) == sizeof(fb_A_data));
  }
}
