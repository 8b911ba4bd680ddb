// The application at its edges (each case a defect once found and fixed): time arithmetic
// near LTIME::max(), outputs written while the instances are constructed, scratch instances
// holding programs, retained data when the storage fails, small retain memories, the
// watchdog's product, and event sampling after a cycle ends.
#include "iecoop_test.hpp"

#include <iecoop/runtime/application.hpp>

using namespace iecoop;
using iecoop_test::fault_recorder;

namespace {

LTIME ms(std::uint64_t n) { return LTIME::from_ticks(n * 1000000U); }

struct COUNT_PRG : program<COUNT_PRG> {
  var<UDINT> nCalls;
  void body() { nCalls = nCalls + 1U; }
};

// A located output with an initial value, written by the constructor (ST: bLamp AT %QX0.0 : BOOL := TRUE;).
struct edge_tag {};
using edge_image = process_image<4, 4, 4, addressing::codesys, edge_tag>;
struct LAMP_PRG : program<LAMP_PRG> {
  [[no_unique_address]] located<BOOL, "%QX0.0", edge_image> bLamp;
  using LOCATED = pins<&LAMP_PRG::bLamp>;
  LAMP_PRG() { bLamp = TRUE; }
  void body() {}
};

// A program that only another list's member is: owned through globals<GVL_Sub>.
struct SUB_PRG : program<SUB_PRG> {
  void body() {}
};
struct GVL_Sub {
  SUB_PRG sub;
};

struct RETAIN_PRG : program<RETAIN_PRG> {
  retain<DINT> nParts;
  void body() { nParts = nParts + 1; }
};

// OUT_PRG sets %QX0.0 in its third cycle; IRQ_PRG is the event task on that output as the
// field sees it (written when OUT_PRG's cycle ends).
simulated_io<edge_image> field;
struct OUT_PRG : program<OUT_PRG> {
  [[no_unique_address]] located<BOOL, "%QX0.1", edge_image> bOut;
  using LOCATED = pins<&OUT_PRG::bOut>;
  var<UDINT> nCalls;
  void body() {
    nCalls = nCalls + 1U;
    if (nCalls == 3U) bOut = TRUE;
  }
};
struct IRQ_PRG : program<IRQ_PRG> {
  LTIME at{};
  void body() { at = cycle_clock::now(); }
};

}  // namespace

TEST_SUITE("application: edge cases") {
  TEST_CASE("run_for(LTIME::max()) after some time runs on (it stopped at once when now + d wrapped)") {
    application plc{task<COUNT_PRG>{"T", cyclic{"T#1ms"_iec}, 0, watchdog{"T#1ms"_iec}}};
    plc.task(0).model_execution_time([](std::uint64_t n, void*) { return n == 5 ? LTIME(TIME(2)) : LTIME{}; });
    fault_recorder faults;
    plc.start();
    plc.run_for(ms(1));
    plc.run_for(LTIME::max());  // ends with the watchdog fault of cycle 5
    CHECK(faults.count == 1);
    CHECK(COUNT_PRG::instance().nCalls == 6U);
    CHECK(plc.now() == LTIME::max());
  }

  TEST_CASE("a release grid near LTIME::max() neither wraps nor loops") {
    application plc{task<COUNT_PRG>{"T", cyclic{LTIME::from_ticks(1ULL << 63)}, 0}};
    plc.start();
    plc.run_until(LTIME::max());                // returned only because the next release saturates to "never"
    CHECK(COUNT_PRG::instance().nCalls == 2U);  // at 0 and at 2^63 ns
    CHECK(plc.task(0).statistics().overruns == 0);
  }

  TEST_CASE("a cycle modelled to never end does not end in the past") {
    application plc{task<COUNT_PRG>{"T", cyclic{"T#10ms"_iec}, 0}};
    plc.start();
    plc.run_for(ms(10));
    plc.task(0).model_execution_time(LTIME::max());
    plc.run_for(ms(30));
    CHECK(plc.task(0).statistics().cycles == 1);
    CHECK(plc.task(0).statistics().max_cycle_time == LTIME{});
    CHECK(plc.task(0).statistics().overruns == 2);  // the releases at 20 and 30 ms
  }

  TEST_CASE("outputs written while the instances are constructed reach the field") {
    application plc{task<LAMP_PRG>{"T", cyclic{"T#1ms"_iec}, 0}, use_image<edge_image>{}};
    simulated_io<edge_image> lamp_field;
    plc.connect(lamp_field);
    plc.start();
    plc.run_for(ms(2));
    CHECK(lamp_field.output<"%QX0.0">() == TRUE);
    CHECK(plc.published_outputs()[0] == std::byte{1});
    plc.reset(reset_kind::cold);  // and again after a reset
    plc.start();
    plc.run_for(ms(1));
    CHECK(lamp_field.output<"%QX0.0">() == TRUE);
  }

  TEST_CASE("a scratch list made before start does not register the programs inside it") {
    application plc{task<COUNT_PRG>{"T", cyclic{"T#1ms"_iec}, 0}, globals<GVL_Sub>{}};
    fault_recorder faults;
    (void)plc.get<GVL_Sub>();  // before start: a fault, and a scratch list
    CHECK(faults.count == 1);
    CHECK_FALSE(SUB_PRG::exists());
    plc.start();
    CHECK(faults.count == 1);  // no duplicate_program
    CHECK(&SUB_PRG::instance() == &plc.get<GVL_Sub>().sub);
  }

  TEST_CASE("when the storage refuses the data, a restart in the same application keeps it") {
    memory_storage<8> too_small;
    fault_recorder faults;
    application plc{task<RETAIN_PRG>{"T", cyclic{"T#1ms"_iec}, 0}};
    plc.use_storage(too_small);
    plc.start();
    plc.run_for(ms(5));
    plc.stop();
    CHECK(faults.count == 1);
    plc.start();
    CHECK(RETAIN_PRG::instance().nParts == 5);
  }

  TEST_CASE("an application without remanent variables needs no retain memory") {
    application plc{task<COUNT_PRG>{"T", cyclic{"T#1ms"_iec}, 0}, retain_capacity<0>{}};
    fault_recorder faults;
    plc.start();
    plc.reset(reset_kind::warm);
    plc.start();
    plc.stop();
    CHECK(faults.count == 0);
  }

  TEST_CASE("a watchdog time x sensitivity beyond LTIME's range is no single timeout") {
    application plc{task<COUNT_PRG>{"T", cyclic{"T#20s"_iec}, 0, watchdog{LTIME::from_ticks(1ULL << 33), 1U << 31}}};
    plc.task(0).model_execution_time(LTIME(TIME(9000)));  // 9 s > 2^33 ns (8.6 s): an overrun, not a fault
    fault_recorder faults;
    plc.start();
    plc.run_for(LTIME(TIME(10000)));
    CHECK(faults.count == 0);
    CHECK(plc.task(0).statistics().watchdog_overruns == 1);
  }

  TEST_CASE("event conditions are sampled again after a cycle ends") {
    application plc{task<OUT_PRG>{"Out", cyclic{"T#10ms"_iec}, 1},
                    task<IRQ_PRG>{"Irq", event{[] { return field.output<"%QX0.1">(); }}, 0}, use_image<edge_image>{}};
    plc.connect(field);
    plc.start();
    plc.run_for(ms(40));
    CHECK(IRQ_PRG::instance().at == ms(20));  // the field sees the output at the end of the cycle at 20 ms
  }
}
