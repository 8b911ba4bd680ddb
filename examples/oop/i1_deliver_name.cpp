// Seed: CODESYS "Object 'Interface'" (English page), the example — the interface I1 with the
// method GetName, the blocks A and B implementing it, and the FUNCTION DeliverName whose
// input is a variable of type I1: "it depends on the actual type of l_i whether the
// application calls A.GetName or B.GetName."
//
// The seed leaves out the bodies of A.GetName and B.GetName; ours return 'A' and 'B'.
#include <doctest/doctest.h>

#include <iecoop/iecoop.hpp>
#include <iecoop/ostream.hpp>

namespace seed_i1 {

using namespace iecoop;

// INTERFACE I1
struct I1 : interface_base<I1> {
  // METHOD GetName : STRING
  virtual STRING<> GetName() = 0;
};

// FUNCTION_BLOCK A IMPLEMENTS I1
struct A : function_block<A, implements<I1>> {
  STRING<> GetName() override { return "A"; }  // GetName := 'A';   (ours)
};

// FUNCTION_BLOCK B IMPLEMENTS I1
struct B : function_block<B, implements<I1>> {
  STRING<> GetName() override { return "B"; }  // GetName := 'B';   (ours)
};

// FUNCTION DeliverName : STRING
// VAR_INPUT
//     l_i : I1;
// END_VAR
struct DeliverName_vars {
  itf<I1> l_i;
};
inline constexpr function DeliverName = [](args<DeliverName_vars> in) -> STRING<> {
  return in.l_i->GetName();  // DeliverName := l_i.GetName();
};

}  // namespace seed_i1

using namespace iecoop;
using seed_i1::A;
using seed_i1::B;
using seed_i1::DeliverName;
using seed_i1::I1;

TEST_SUITE("seed: I1, A, B and DeliverName") {
  TEST_CASE("the call reaches the GetName of the instance passed") {
    A A_instance;
    B B_instance;
    CHECK(DeliverName("l_i"_ = A_instance) == "A");  // DeliverName(l_i := A_instance);  // call with instance of type A
    CHECK(DeliverName("l_i"_ = B_instance) == "B");  // DeliverName(l_i := B_instance);  // call with instance of type B
    CHECK(DeliverName(A_instance) == "A");           // positionally
  }

  TEST_CASE("an interface variable assigned before the call (l_i := A_instance)") {
    A A_instance;
    B B_instance;
    itf<I1> l_i;
    CHECK(l_i == 0);  // 0 until assigned
    l_i = A_instance;
    CHECK(DeliverName(l_i) == "A");
    l_i = B_instance;
    CHECK(DeliverName(l_i) == "B");
  }
}
