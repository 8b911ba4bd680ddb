// The application's lifecycle: start (FB_Init), stop (FB_Exit), warm / cold / origin reset,
// controller restart and new download, with RETAIN and PERSISTENT variables in programs and
// global variable lists behaving as in the table of docs/retain.md ("What survives which
// event"), and retained data
// kept in memory, in a memory_storage or in a file.
#include "iecoop_test.hpp"

#include <iecoop/runtime/application.hpp>
#include <iecoop/runtime/file_storage.hpp>

#include <cstdio>
#include <string>

using namespace iecoop;
using iecoop_test::fault_recorder;

namespace {

std::string events;  // FB_Init / FB_Exit calls with their flags

// PROGRAM MACHINE_PRG
//   VAR            nCycles : INT;        END_VAR
//   VAR RETAIN     nParts : DINT;        END_VAR
//   VAR PERSISTENT nHours : UDINT := 100; END_VAR
struct MACHINE_PRG : program<MACHINE_PRG> {
  MACHINE_PRG() { run_fb_init(*this); }
  ~MACHINE_PRG() { run_fb_exit(*this); }
  MACHINE_PRG(const MACHINE_PRG&) = default;
  MACHINE_PRG& operator=(const MACHINE_PRG&) = default;

  var<INT> nCycles;
  retain<DINT> nParts{0};
  persistent<UDINT> nHours{100U};

  void body() {
    nCycles = nCycles + 1;
    nParts = nParts + 1;
    nHours = nHours + 1U;
  }

 private:
  friend struct iecoop::block_access;
  BOOL FB_Init(BOOL bInitRetains, BOOL bInCopyCode) {
    events += std::string("init:") + (bInitRetains ? "T" : "F") + (bInCopyCode ? "T" : "F") + " ";
    return TRUE;
  }
  BOOL FB_Exit(BOOL bInCopyCode) {
    events += std::string("exit:") + (bInCopyCode ? "T" : "F") + " ";
    return TRUE;
  }
};

// VAR_GLOBAL RETAIN / PERSISTENT, and a plain one, in one list.
struct GVL_Plant : global_variables<GVL_Plant> {
  retain<INT> iShift{INT(1)};
  persistent<REAL> rTotal{REAL(0.5f)};
  INT iPlain = 7;
};

LTIME ms(std::uint64_t n) { return LTIME::from_ticks(n * 1000000U); }

// Runs five cycles and changes the global list, so that every variable differs from its
// initial value.
template <class App>
void run_and_change(App& plc) {
  plc.start();
  plc.run_for(ms(5));
  GVL_Plant& gvl = plc.template get<GVL_Plant>();
  gvl.iShift = 3;
  gvl.rTotal = REAL(2.5f);
  gvl.iPlain = 9;
}

// The application under test (returned as a prvalue: applications are neither copied nor moved).
auto make_plant() { return application{task<MACHINE_PRG>{"Main", cyclic{"T#1ms"_iec}, 1}, globals<GVL_Plant>{}}; }

}  // namespace

TEST_SUITE("application: start and stop") {
  TEST_CASE("start constructs the instances (FB_Init), stop ends them (FB_Exit)") {
    events.clear();
    {
      auto plc = make_plant();
      CHECK(plc.state() == application_state::stopped);
      CHECK_FALSE(MACHINE_PRG::exists());
      CHECK(plc.start());
      CHECK(events == "init:TF ");  // first start: bInitRetains = TRUE
      CHECK(plc.state() == application_state::running);
      CHECK(MACHINE_PRG::exists());
      CHECK(&plc.get<MACHINE_PRG>() == &MACHINE_PRG::instance());
      plc.run_for(ms(3));
      CHECK(MACHINE_PRG::instance().nCycles == 3);
      plc.stop();
      CHECK(events == "init:TF exit:F ");
      CHECK(plc.state() == application_state::stopped);
      CHECK_FALSE(MACHINE_PRG::exists());
      plc.stop();  // a second stop does nothing
      CHECK(events == "init:TF exit:F ");
      plc.start();
    }
    // The application's end stops it.
    CHECK(events == "init:TF exit:F init:FF exit:F ");
    CHECK_FALSE(MACHINE_PRG::exists());
  }

  TEST_CASE("a global variable list the application owns is reached by its name while it runs") {
    auto plc = make_plant();
    CHECK_FALSE(GVL_Plant::exists());
    plc.start();
    CHECK(GVL_Plant::exists());
    CHECK(&GVL_Plant::instance() == &plc.get<GVL_Plant>());
    GVL_Plant::instance().iShift = 2;  // ST: GVL_Plant.iShift := 2;
    CHECK(plc.get<GVL_Plant>().iShift == 2);
    plc.stop();
    CHECK_FALSE(GVL_Plant::exists());
  }

  TEST_CASE("get before start reports a fault and yields a scratch instance") {
    auto plc = make_plant();
    fault_recorder faults;
    GVL_Plant& scratch = plc.get<GVL_Plant>();
    CHECK(faults.count == 1);
    CHECK(faults.last_kind == fault_kind::invalid_value);
    CHECK(scratch.iPlain == 7);
    (void)plc.get<MACHINE_PRG>();
    CHECK(faults.count == 2);
  }

  TEST_CASE("a reset of a stopped application does nothing") {
    events.clear();
    auto plc = make_plant();
    plc.reset(reset_kind::cold);
    CHECK(plc.state() == application_state::stopped);
    CHECK(events.empty());
  }
}

TEST_SUITE("application: resets and RETAIN / PERSISTENT (docs/retain.md, what survives which event)") {
  TEST_CASE("warm reset: VAR initialised, RETAIN and PERSISTENT kept") {
    auto plc = make_plant();
    run_and_change(plc);
    events.clear();
    plc.reset(reset_kind::warm);
    CHECK(events == "exit:F init:FF ");
    CHECK(plc.state() == application_state::halted);
    const MACHINE_PRG& m = plc.get<MACHINE_PRG>();
    CHECK(m.nCycles == 0);
    CHECK(m.nParts == 5);
    CHECK(m.nHours == 105U);
    const GVL_Plant& g = plc.get<GVL_Plant>();
    CHECK(g.iShift == 3);
    CHECK(g.rTotal == REAL(2.5f));
    CHECK(g.iPlain == 7);
    // Halted until started again.
    plc.run_for(ms(5));
    CHECK(MACHINE_PRG::instance().nCycles == 0);
    plc.start();
    plc.run_for(ms(2));
    CHECK(MACHINE_PRG::instance().nParts == 7);
  }

  TEST_CASE("cold reset: VAR and RETAIN initialised, PERSISTENT kept") {
    auto plc = make_plant();
    run_and_change(plc);
    events.clear();
    plc.reset(reset_kind::cold);
    CHECK(events == "exit:F init:TF ");
    CHECK(MACHINE_PRG::instance().nParts == 0);
    CHECK(MACHINE_PRG::instance().nHours == 105U);
    CHECK(plc.get<GVL_Plant>().iShift == 1);
    CHECK(plc.get<GVL_Plant>().rTotal == REAL(2.5f));
    CHECK(plc.get<GVL_Plant>().iPlain == 7);
  }

  TEST_CASE("reset origin: everything initialised") {
    auto plc = make_plant();
    run_and_change(plc);
    plc.reset(reset_kind::origin);
    CHECK(MACHINE_PRG::instance().nParts == 0);
    CHECK(MACHINE_PRG::instance().nHours == 100U);
    CHECK(plc.get<GVL_Plant>().iShift == 1);
    CHECK(plc.get<GVL_Plant>().rTotal == REAL(0.5f));
  }

  TEST_CASE("controller restart: stop and start keep RETAIN and PERSISTENT in the retain memory") {
    auto plc = make_plant();
    run_and_change(plc);
    plc.stop();
    events.clear();
    plc.start();
    CHECK(events == "init:FF ");  // retained data found: bInitRetains = FALSE
    CHECK(MACHINE_PRG::instance().nCycles == 0);
    CHECK(MACHINE_PRG::instance().nParts == 5);
    CHECK(MACHINE_PRG::instance().nHours == 105U);
    CHECK(plc.get<GVL_Plant>().iShift == 3);
    CHECK(plc.get<GVL_Plant>().iPlain == 7);
  }

  TEST_CASE("new download: RETAIN initialised, PERSISTENT kept") {
    auto plc = make_plant();
    run_and_change(plc);
    plc.stop();
    events.clear();
    plc.start(start_mode::download);
    CHECK(events == "init:TF ");
    CHECK(MACHINE_PRG::instance().nParts == 0);
    CHECK(MACHINE_PRG::instance().nHours == 105U);
    CHECK(plc.get<GVL_Plant>().iShift == 1);
    CHECK(plc.get<GVL_Plant>().rTotal == REAL(2.5f));
  }

  TEST_CASE("a reset clears the task statistics") {
    auto plc = make_plant();
    plc.start();
    plc.run_for(ms(4));
    CHECK(plc.task(0).statistics().cycles == 4);
    plc.reset(reset_kind::warm);
    CHECK(plc.task(0).statistics().cycles == 0);
  }
}

namespace {

/// Removes a file_storage's file and the images it keeps beside it (`.previous`, `.rejected`):
/// a stale previous image would be found by the next run of the test.
void remove_storage_files(const std::string& path) {
  for (const char* suffix : {"", ".previous", ".rejected"}) std::remove((path + suffix).c_str());
}

}  // namespace

TEST_SUITE("application: retained data in a storage") {
  TEST_CASE("a file keeps RETAIN and PERSISTENT over the end of the process") {
    const char* path = "iecoop_application_lifecycle_test_restart.bin";
    remove_storage_files(path);
    {
      file_storage storage(path);
      auto plc = make_plant();
      plc.use_storage(storage);
      run_and_change(plc);
    }  // the application ends: stop() writes the file
    {
      file_storage storage(path);
      auto plc = make_plant();
      plc.use_storage(storage);
      events.clear();
      plc.start();  // a controller restart in a new application (a new process, in real life)
      CHECK(events == "init:FF ");
      CHECK(MACHINE_PRG::instance().nParts == 5);
      CHECK(MACHINE_PRG::instance().nHours == 105U);
      CHECK(plc.get<GVL_Plant>().iShift == 3);
      CHECK(plc.get<GVL_Plant>().rTotal == REAL(2.5f));
      CHECK(plc.get<GVL_Plant>().iPlain == 7);
      plc.run_for(ms(1));
      plc.stop();
      plc.start(start_mode::download);
      CHECK(MACHINE_PRG::instance().nParts == 0);
      CHECK(MACHINE_PRG::instance().nHours == 106U);
    }
    remove_storage_files(path);
  }

  TEST_CASE("without saved data, start is a first start") {
    const char* path = "iecoop_application_lifecycle_test_missing.bin";
    remove_storage_files(path);
    file_storage storage(path);
    auto plc = make_plant();
    plc.use_storage(storage);
    events.clear();
    plc.start();
    CHECK(events == "init:TF ");
    CHECK(MACHINE_PRG::instance().nHours == 100U);
    plc.stop();
    remove_storage_files(path);
  }

  TEST_CASE("save_retained writes the values now") {
    memory_storage<256> storage;
    auto plc = make_plant();
    CHECK_FALSE(plc.save_retained());  // no storage yet
    plc.use_storage(storage);
    CHECK_FALSE(plc.save_retained());  // no instances yet
    run_and_change(plc);
    CHECK(plc.save_retained());
    CHECK(storage.size() > 0);
    const std::size_t saved = storage.size();
    plc.run_for(ms(1));
    CHECK(plc.save_retained());
    CHECK(storage.size() == saved);
    // What was saved is what a restart in another application finds.
    plc.stop();
    auto other = make_plant();
    other.use_storage(storage);
    other.start();
    CHECK(MACHINE_PRG::instance().nParts == 6);
    CHECK(MACHINE_PRG::instance().nHours == 106U);
    CHECK(other.get<GVL_Plant>().iShift == 3);
  }

  TEST_CASE("a retain memory too small for the retained variables is a fault at start, not a loss at a reset") {
    fault_recorder faults;
    application plc{task<MACHINE_PRG>{"Main", cyclic{"T#1ms"_iec}, 1}, retain_capacity<8>{}};
    events.clear();
    CHECK_FALSE(plc.start());
    CHECK(faults.count == 1);
    CHECK(faults.last_kind == fault_kind::invalid_value);
    CHECK(events == "init:TF exit:F ");
    CHECK(plc.state() == application_state::stopped);
    plc.reset(reset_kind::warm);  // nothing to reset
    plc.stop();
    CHECK(faults.count == 1);
  }
}

TEST_CASE("a storage that cannot save the retained data is a fault") {
  fault_recorder faults;
  memory_storage<8> tiny;  // smaller than the image
  auto plc = make_plant();
  plc.use_storage(tiny);
  plc.start();
  plc.stop();
  CHECK(faults.count == 1);
  CHECK(faults.last_kind == fault_kind::invalid_value);
  CHECK(tiny.size() == 0);
}
