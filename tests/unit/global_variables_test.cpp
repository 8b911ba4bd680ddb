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
    CHECK(faults.last_message.starts_with("GVL_Test: a global variable list has exactly one instance"));
    CHECK(faults.last_pou == "GVL_Test");  // the fault's pou names the list it is about
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

  TEST_CASE("the fault of a list no application lists names the list and globals<...>") {
    fault_recorder faults;
    (void)GVL_Test::instance();
    CHECK(faults.count == 1);
    CHECK(faults.last_message ==
          "GVL_Test: no application lists this global variable list in globals<...> and no instance of it is "
          "declared; add it to the application, as in application{..., globals<GVL_Test>{}} (or declare its one "
          "instance yourself); a scratch instance stands in");
  }

  TEST_CASE("the fault of a listed list while its application is stopped names the list and start()") {
    fault_recorder faults;
    {
      application plc{task<MODE_PRG>{"Main", cyclic{"T#10ms"_iec}, 1}, globals<GVL_Test>{}};
      (void)GVL_Test::instance();  // before start()
      CHECK(faults.count == 1);
      CHECK(faults.last_message ==
            "GVL_Test: used while its application is stopped (before start() or after stop()); start() constructs it "
            "— a scratch instance stands in");
      CHECK(faults.last_pou == "GVL_Test");
      plc.start();
      CHECK(&GVL_Test::instance() == &plc.get<GVL_Test>());
      CHECK(faults.count == 1);
      plc.stop();
      (void)plc.get<GVL_Test>();  // after stop()
      CHECK(faults.count == 2);
      CHECK(faults.last_message.starts_with("GVL_Test: used while its application is stopped"));
    }
    (void)GVL_Test::instance();  // the application has ended: no application lists it now
    CHECK(faults.count == 3);
    CHECK(faults.last_message.starts_with("GVL_Test: no application lists this global variable list"));
  }

  TEST_CASE("a program that is in no task: the fault names it and task<...>") {
    fault_recorder faults;
    (void)MODE_PRG::instance();
    CHECK(faults.count == 1);
    CHECK(faults.last_kind == fault_kind::invalid_value);
    CHECK(faults.last_message ==
          "MODE_PRG: no task of an application calls this PROGRAM and no instance of it is declared; name it in a "
          "task of the application, as in application{task<MODE_PRG>{\"Main\", cyclic{\"T#10ms\"_iec}, 1}} (or "
          "declare its one instance yourself); a scratch instance stands in");
    CHECK(faults.last_pou == "MODE_PRG");
    MODE_PRG first;
    MODE_PRG second;
    CHECK(faults.last_kind == fault_kind::duplicate_program);
    CHECK(faults.last_message.starts_with("MODE_PRG: a PROGRAM has exactly one instance"));
    CHECK(faults.last_pou == "MODE_PRG");
  }

  TEST_CASE("a program's VAR_EXTERNAL names the lists it uses; the application that lists them runs it") {
    struct USES_PRG : program<USES_PRG> {
      using VAR_EXTERNAL = globals<GVL_Test>;  // VAR_EXTERNAL: the lists this program uses
      void body() { GVL_Test::instance().iMode = GVL_Test::instance().iMode + 1; }
    };
    application plc{task<USES_PRG>{"Main", cyclic{"T#10ms"_iec}, 1}, globals<GVL_Test>{}};
    plc.start();
    plc.run_cycles(3);
    CHECK(plc.get<GVL_Test>().iMode == 4);
  }
}
