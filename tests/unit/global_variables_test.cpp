// Global variable lists: one instance, reached by the list's name from any POU.
#include "iecoop_test.hpp"

using namespace iecoop;
using iecoop_test::fault_recorder;

namespace {

// VAR_GLOBAL  iMode : INT := 1;  bAuto : BOOL;  END_VAR
struct GVL_Test : global_variables<GVL_Test> {
  INT iMode = 1;
  BOOL bAuto;
};

// A program that reads and writes the list by its name, as ST does.
struct MODE_PRG : program<MODE_PRG> {
  void body() {
    if (GVL_Test::instance().bAuto) GVL_Test::instance().iMode = 2;  // IF GVL_Test.bAuto THEN GVL_Test.iMode := 2;
  }
};

}  // namespace

TEST_SUITE("global variable lists") {
  TEST_CASE("the one instance is reached by the list's name") {
    CHECK_FALSE(GVL_Test::exists());
    {
      GVL_Test gvl;
      MODE_PRG mode;
      CHECK(GVL_Test::exists());
      CHECK(&GVL_Test::instance() == &gvl);
      gvl.bAuto = TRUE;
      mode();
      CHECK(gvl.iMode == 2);
    }
    CHECK_FALSE(GVL_Test::exists());
  }

  TEST_CASE("a second instance is a fault and is not the list") {
    GVL_Test first;
    fault_recorder faults;
    GVL_Test second;
    CHECK(faults.count == 1);
    CHECK(faults.last_kind == fault_kind::duplicate_globals);
    CHECK(&GVL_Test::instance() == &first);
    CHECK(std::string(to_string(fault_kind::duplicate_globals)) == "second instance of a global variable list");
  }

  TEST_CASE("a copy is not registered, and its end leaves the list in place") {
    GVL_Test gvl;
    {
      const GVL_Test copy = gvl;
      CHECK(&GVL_Test::instance() == &gvl);
      CHECK(copy.iMode == 1);
    }
    CHECK(GVL_Test::exists());
  }

  TEST_CASE("without an instance, instance() is a fault and yields a scratch list") {
    fault_recorder faults;
    GVL_Test& scratch = GVL_Test::instance();
    CHECK(faults.count == 1);
    CHECK(faults.last_kind == fault_kind::invalid_value);
    CHECK(scratch.iMode == 1);
    CHECK_FALSE(GVL_Test::exists());
  }
}
