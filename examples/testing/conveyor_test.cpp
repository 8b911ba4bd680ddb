// Unit tests of the demo's conveyor (examples/conveyor.hpp) written with iecoop's test kit,
// <iecoop/testing.hpp>, as a PLC engineer would write them for a design of their own: the
// application's PLC tasks run in simulated time (T#2s of machine time take a few milliseconds),
// the tests force and write the inputs as CODESYS's online mode does, and wait with timeouts.
//
// Two ways in:
//   - testing::plc<make_plc>: a fixture that owns the application made of the PLC's tasks (Fast:
//     IO_PRG every T#1ms, Slow: SUPERVISION_PRG every T#20ms, and the global variable lists),
//     started; step() runs one base cycle (T#1ms), so SUPERVISION_PRG runs every 20th step.
//   - testing::cycles: one block alone (FB_Conveyor, FB_VfdMotor), called once per cycle.
//
// The demo's simulation (the operator, the belt and its parts: task Sim) is not part of the
// application under test: the tests are the field. They set the located inputs (%I) with
// force() and write() (a program may not assign them); with no I/O driver connected, a value
// written stays until written again. STOP is normally closed: the fixture forces it TRUE.
//
// Build: link the CMake target iecoop::testing_main (doctest's main() with the kit), or define
// IECOOP_TESTING_MAIN before including <iecoop/testing.hpp> in one file.
#include <iecoop/testing.hpp>

#include <cstddef>
#include <cstdint>
#include <string_view>

#include "conveyor.hpp"

using namespace iecoop;
using demo::E_Motor;
using demo::FB_Conveyor;
using demo::FB_DolMotor;
using demo::FB_VfdMotor;
using demo::GVL;
using demo::GVL_Config;
using demo::GVL_IO;
using demo::IO_PRG;
using demo::SUPERVISION_PRG;

namespace {

// The application under test: the PLC's task configuration of demo::make_conveyor(), without
// the simulation's task Sim.
auto make_plc() {
  return application{
      task<IO_PRG>{"Fast", cyclic{"T#1ms"_iec}, 0, watchdog{"T#2ms"_iec, 2}},
      task<SUPERVISION_PRG>{"Slow", cyclic{"T#20ms"_iec}, 5, watchdog{"T#15ms"_iec, 2}},
      globals<GVL_IO, GVL, GVL_Config>{},
  };
}

// The fixture: each test case gets a new application, started (FB_Init), and stopped after it.
struct ConveyorPlc : testing::plc<make_plc> {
  GVL_IO& io = get<GVL_IO>();
  GVL& gvl = get<GVL>();
  GVL_Config& config = get<GVL_Config>();
  IO_PRG& prg = get<IO_PRG>();
  SUPERVISION_PRG& supervision = get<SUPERVISION_PRG>();

  ConveyorPlc() {
    force(io.ixStop, TRUE);  // STOP is normally closed: TRUE while nobody presses it
  }

  // The operator presses START for one cycle.
  void press_start() { pulse(io.ixStart); }
  // A part passes the eye: blocked for `blocked` cycles, then clear for `gap`.
  void part(std::uint64_t blocked = 30, std::uint64_t gap = 30) {
    pulse(io.ixPartEye, blocked);
    step(gap);
  }
};

// 16#4000 on the speed reference is 100 % (PROFIdrive N2).
constexpr INT speed_ref_100 = INT(0x4000);

}  // namespace

TEST_SUITE("IO_PRG") {
  TEST_CASE_FIXTURE(ConveyorPlc, "START latches the belt on, STOP (normally closed) drops it") {
    step();
    CHECK_FALSE(gvl.bRunning);
    CHECK_FALSE(io.qxMotor);

    press_start();
    CHECK(gvl.bRunning);
    CHECK(io.qxMotor);
    step(500);  // START was released long ago: the latch holds
    CHECK(gvl.bRunning);
    CHECK(io.qxMotor);

    pulse(io.ixStop, 1, FALSE);  // STOP pressed: the contact opens
    CHECK_FALSE(gvl.bRunning);
    CHECK(forced(io.ixStop));  // the pulse gave the force back
    CHECK(io.ixStop);
    step(100);
    CHECK_FALSE(gvl.bRunning);
  }

  TEST_CASE_FIXTURE(ConveyorPlc, "STOP dominates START, and a broken STOP wire stops the belt") {
    pulse(io.ixStop, 1, FALSE);  // pressed and let go: nothing to stop, and nothing kept
    CHECK(io.ixStop);
    press_start();
    CHECK(gvl.bRunning);
    pulse(io.ixStop, 1, FALSE);
    CHECK_FALSE(gvl.bRunning);

    force(io.ixStop, FALSE);  // pressed (or the wire is broken)
    pulse(io.ixStart, 5);
    CHECK_FALSE(gvl.bRunning);

    force(io.ixStop, TRUE);
    press_start();
    REQUIRE(gvl.bRunning);
    release(io.ixStop);
    write(io.ixStop, FALSE);  // the wire breaks: the input reads FALSE, as a pressed button
    step();
    CHECK_FALSE(gvl.bRunning);
    CHECK_FALSE(forced(io.ixStop));
  }

  TEST_CASE_FIXTURE(ConveyorPlc, "timing diagram of the start/stop latch (DOL motor: the contactor follows at once)") {
    config.eMotor = E_Motor::DOL;
    release(io.ixStop);  // the diagram drives STOP itself: a force would win over it
    CHECK(testing::run_diagram(*this,  // one column per base cycle (T#1ms)
                               testing::drive("ixStart", io.ixStart, "_##_____#####___"),
                               testing::drive("ixStop", io.ixStop, "#####__####__###"),
                               testing::expect("bRunning", gvl.bRunning, "_####___###_____"),
                               testing::expect("qxMotor", io.qxMotor, "_####___###_____"),
                               testing::expect("qxJamLamp", io.qxJamLamp, "________________")));
  }

  TEST_CASE_FIXTURE(ConveyorPlc, "a part at the eye for exactly T#2s while running is a jam: lamp on, belt off") {
    config.eMotor = E_Motor::DOL;
    press_start();
    REQUIRE(io.qxMotor);

    force(io.ixPartEye, TRUE);
    step();  // the first cycle that sees the eye blocked: the jam timer starts here
    advance("T#1s999ms"_iec);
    CHECK(prg.fbConveyor.tJam.ET == "T#1s999ms"_iec);
    CHECK_FALSE(gvl.bJam);
    CHECK_FALSE(io.qxJamLamp);
    CHECK(io.qxMotor);

    step();  // T#2s after the eye was first seen blocked
    CHECK(gvl.bJam);
    CHECK(io.qxJamLamp);
    CHECK_FALSE(gvl.bRunning);
    CHECK_FALSE(io.qxMotor);  // the contactor drops in the same cycle

    force(io.ixPartEye, FALSE);  // the part is taken away: the jam stays latched until RESET
    step(1000);
    CHECK(io.qxJamLamp);
    press_start();  // and the belt does not start meanwhile
    CHECK_FALSE(gvl.bRunning);
    CHECK_FALSE(io.qxMotor);
  }

  TEST_CASE_FIXTURE(ConveyorPlc, "run_until: the jam comes T#2s after the eye is blocked, not sooner") {
    press_start();
    force(io.ixPartEye, TRUE);
    // Checked before each cycle and after it: cycle 1 sees the eye, cycle 2001 (T#2s later) the jam.
    const testing::wait_result jam = run_until(gvl.bJam, "T#3s"_iec);
    REQUIRE(jam);
    CHECK(jam.cycles == 2001);
    CHECK(jam.waited == LTIME("T#2s1ms"_iec));

    // The VFD ramps down from the setpoint before the drive is disabled (bEnable := bRun OR rRamp > 0).
    CHECK(io.qxMotor);
    CHECK_FALSE(gvl.bRunning);
    CHECK_FALSE(run_until([&] { return !io.qxMotor; }, "T#150ms"_iec));  // 20 % at 100 %/s: T#200ms
    CHECK(run_until([&] { return !io.qxMotor; }, "T#60ms"_iec));
    CHECK(io.qwSpeedRef == 0);
  }

  TEST_CASE_FIXTURE(ConveyorPlc, "no jam while the belt stands, however long the eye is blocked") {
    force(io.ixPartEye, TRUE);
    CHECK_FALSE(run_until(gvl.bJam, "T#10s"_iec));
    CHECK_FALSE(io.qxJamLamp);
    CHECK(gvl.wParts == 1);  // counted once: on the eye's rising edge
  }

  TEST_CASE_FIXTURE(ConveyorPlc, "DOL motor: the contactor, full speed at once, no speed reference") {
    config.eMotor = E_Motor::DOL;
    write(io.iwSpeed, INT(60));
    press_start();
    CHECK(io.qxMotor);
    CHECK(prg.fbDol.bContactor);
    CHECK(gvl.bAtSpeed);  // one speed: at speed as soon as it runs
    CHECK(gvl.rSpeed == 100.0f);
    CHECK(io.qwSpeedRef == 0);
    CHECK_FALSE(prg.fbVfd.bEnable);  // the inverter is not called

    pulse(io.ixStop, 1, FALSE);
    CHECK_FALSE(io.qxMotor);
    CHECK_FALSE(gvl.bAtSpeed);
    CHECK(gvl.rSpeed == 0.0f);
  }

  TEST_CASE_FIXTURE(ConveyorPlc, "VFD motor: enable at once, the speed reference ramps 0 to 16#4000 in T#1s") {
    REQUIRE(config.eMotor == E_Motor::VFD);  // GVL_Config's initial value
    write(io.iwSpeed, INT(100));
    step();
    press_start();  // the first cycle of the ramp
    CHECK(io.qxMotor);
    CHECK(io.qwSpeedRef == 16);  // 0.1 % per T#1ms: REAL_TO_INT(0.1 * 163.84)
    CHECK_FALSE(gvl.bAtSpeed);

    advance("T#499ms"_iec);  // half way: 50 %
    CHECK(io.qwSpeedRef == 0x2000);
    CHECK(gvl.rSpeed > 49.9f);
    CHECK(gvl.rSpeed < 50.1f);
    CHECK_FALSE(gvl.bAtSpeed);

    const testing::wait_result at_speed = run_until(gvl.bAtSpeed, "T#600ms"_iec);
    REQUIRE(at_speed);
    CHECK(at_speed.waited >= LTIME("T#499ms"_iec));  // 500 more steps of 0.1 %, give or take REAL rounding
    CHECK(at_speed.waited <= LTIME("T#502ms"_iec));
    CHECK(io.qwSpeedRef == speed_ref_100);
    CHECK(gvl.rSpeed == 100.0f);

    pulse(io.ixStop, 1, FALSE);  // stop: ramps down, enabled until it stands
    CHECK_FALSE(gvl.bAtSpeed);
    CHECK(io.qxMotor);
    CHECK(io.qwSpeedRef < speed_ref_100);
    CHECK(run_until([&] { return !io.qxMotor; }, "T#1s5ms"_iec));
    CHECK(io.qwSpeedRef == 0);
  }

  TEST_CASE_FIXTURE(ConveyorPlc, "timing diagram of the VFD's first cycles: the speed reference steps 16.384 a cycle") {
    release(io.ixStop);
    CHECK(testing::run_diagram(*this,  // one column per base cycle (T#1ms); iwSpeed is 0: the setpoint is 20 %
                               testing::drive("ixStart", io.ixStart, "_#_______"),
                               testing::drive("ixStop", io.ixStop, "#########"),
                               testing::expect("qxMotor", io.qxMotor, "_########"),
                               testing::expect("qwSpeedRef", io.qwSpeedRef, "0 16 33 49 66 82 98 115 131")));
  }

  TEST_CASE_FIXTURE(ConveyorPlc, "the speed setpoint %IW1 reaches the belt through PROPERTY rSpeed, clamped to 20..100 %") {
    write(io.iwSpeed, INT(60));
    step();
    CHECK(prg.fbConveyor.rSpeed == 60.0f);
    write(io.iwSpeed, INT(150));
    step();
    CHECK(prg.fbConveyor.rSpeed == 100.0f);
    write(io.iwSpeed, INT(10));
    step();
    CHECK(prg.fbConveyor.rSpeed == 20.0f);
    write(io.iwSpeed, INT(-5));
    step();
    CHECK(prg.fbConveyor.rSpeed == 20.0f);

    // 10 % asked for, 20 % it runs: the VFD settles at 20 % (REAL_TO_INT(20 * 163.84) = 3277).
    press_start();
    CHECK(run_until(gvl.bAtSpeed, "T#250ms"_iec));
    CHECK(gvl.rSpeed == 20.0f);
    CHECK(io.qwSpeedRef == 3277);
    // 150 % asked for: 100 %, 16#4000, and no more.
    write(io.iwSpeed, INT(150));
    step();
    CHECK_FALSE(gvl.bAtSpeed);  // the new setpoint is not reached yet
    CHECK(run_until(gvl.bAtSpeed, "T#850ms"_iec));
    CHECK(io.qwSpeedRef == speed_ref_100);
  }

  TEST_CASE_FIXTURE(ConveyorPlc, "forcing %QX0.0 qxMotor: the field sees the forced value, whatever IO_PRG writes") {
    config.eMotor = E_Motor::DOL;
    press_start();
    REQUIRE(io.qxMotor);

    force(io.qxMotor, FALSE);  // the motor held off for maintenance
    step(10);
    CHECK(prg.fbDol.bContactor);  // the program still switches the contactor on ...
    CHECK(gvl.bRunning);
    CHECK_FALSE(io.qxMotor);  // ... but the output is forced
    CHECK((std::to_integer<unsigned>(app().published_outputs()[0]) & 1U) == 0U);  // %QX0.0 as the field sees it
    CHECK(forced(io.qxMotor));
    CHECK(forced_count() == 2);  // with ixStop

    release(io.qxMotor);  // IO_PRG writes it again in the next cycle
    step();
    CHECK(io.qxMotor);
    CHECK((std::to_integer<unsigned>(app().published_outputs()[0]) & 1U) == 1U);

    pulse(io.ixStop, 1, FALSE);
    force(io.qxMotor, TRUE);  // forced on while the belt stands
    step(10);
    CHECK_FALSE(gvl.bRunning);
    CHECK(io.qxMotor);
    release_all();  // STOP too: it keeps its last value (TRUE) in the process image
    step();
    CHECK_FALSE(io.qxMotor);
    CHECK(io.ixStop);
  }

  TEST_CASE_FIXTURE(ConveyorPlc, "GVL_Config.eMotor naming no drive leaves ipMotor unassigned: a fault in task Fast") {
    config.eMotor = static_cast<E_Motor>(2);  // a value of no case (the CASE has no ELSE)
    testing::expect_faults faults;
    step();
    REQUIRE(faults.count() == 1);
    CHECK(faults.last().kind == fault_kind::unassigned_interface);
    REQUIRE(faults.last().task != nullptr);
    REQUIRE(faults.last().pou != nullptr);
    CHECK(std::string_view(faults.last().task) == "Fast");
    CHECK(std::string_view(faults.last().pou) == "IO_PRG");
    // The call could not go on: the application stops, as a PLC's does on an exception.
    CHECK(app().state() == application_state::halted);
    step(10);
    CHECK(faults.count() == 1);
  }
}

TEST_SUITE("SUPERVISION_PRG") {
  TEST_CASE_FIXTURE(ConveyorPlc, "wBatchSize parts fill a box: bBatchDone, udiBatches, and the counter starts again") {
    write(config.wBatchSize, WORD(3));
    press_start();
    part();
    part();
    CHECK(gvl.wParts == 2);
    CHECK_FALSE(gvl.bBatchDone);

    force(io.ixPartEye, TRUE);  // the third part
    step();
    CHECK(gvl.wParts == 3);
    CHECK(gvl.bBatchDone);
    CHECK(supervision.udiBatches == 0);  // SUPERVISION_PRG sees it in its next cycle (T#20ms task)
    // Then IO_PRG resets the counter on GVL.bResetRequest: within one Slow cycle and one Fast cycle.
    CHECK(run_until([&] { return gvl.wParts == 0; }, "T#20ms"_iec));
    CHECK_FALSE(gvl.bBatchDone);
    CHECK(supervision.udiBatches == 1);
    CHECK(supervision.udiParts == 3);
    CHECK(supervision.udiRejected == 0);
    force(io.ixPartEye, FALSE);
    step(30);
    CHECK(gvl.bRunning);  // a full box does not stop the belt

    for (int i = 0; i < 7; ++i) part();  // 7 more: two boxes of 3, one part in the open box
    CHECK(supervision.udiBatches == 3);
    CHECK(gvl.wParts == 1);
    step(20);
    CHECK(supervision.udiParts == 10);
  }

  TEST_CASE_FIXTURE(ConveyorPlc, "a box holds GVL_Config.wBatchSize parts: 8 unless set") {
    press_start();
    for (int i = 0; i < 7; ++i) part();
    CHECK(gvl.wParts == 7);
    CHECK(supervision.udiBatches == 0);
    part();
    CHECK(supervision.udiBatches == 1);
    CHECK(gvl.wParts == 0);
  }

  TEST_CASE_FIXTURE(ConveyorPlc, "RESET acknowledges a jam on its rising edge, only with the eye clear") {
    press_start();
    part();
    part();
    force(io.ixPartEye, TRUE);  // the third part sticks at the eye
    REQUIRE(run_until(gvl.bJam, "T#2s1ms"_iec));
    step(40);
    CHECK(supervision.uiJams == 1);
    CHECK(gvl.wParts == 3);

    pulse(io.ixReset, 200);  // RESET with the part still at the eye: nothing
    CHECK(gvl.bJam);
    CHECK(io.qxJamLamp);
    CHECK(supervision.udiRejected == 0);

    force(io.ixReset, TRUE);  // RESET held while the part is taken away: no rising edge then
    step(40);
    force(io.ixPartEye, FALSE);
    step(40);
    CHECK(gvl.bJam);

    force(io.ixReset, FALSE);
    step(40);
    force(io.ixReset, TRUE);  // pressed again, the eye clear: SUPERVISION_PRG asks IO_PRG to reset
    CHECK(run_until([&] { return !io.qxJamLamp; }, "T#21ms"_iec));
    CHECK_FALSE(gvl.bJam);
    CHECK(gvl.wParts == 0);
    CHECK(supervision.udiRejected == 3);  // the box with the jammed part is rejected, and the two before it
    CHECK(supervision.udiBatches == 0);
    CHECK_FALSE(gvl.bRunning);  // the belt stays off until START
    release(io.ixReset);

    press_start();
    CHECK(gvl.bRunning);
    CHECK(supervision.uiJams == 1);
  }

  TEST_CASE_FIXTURE(ConveyorPlc, "RESET pressed for less than a Slow cycle may pass unseen, T#20ms is always seen") {
    press_start();
    force(io.ixPartEye, TRUE);
    REQUIRE(run_until(gvl.bJam, "T#2s1ms"_iec));
    force(io.ixPartEye, FALSE);
    while (app().now().count() % LTIME("T#20ms"_iec).count() != LTIME("T#1ms"_iec).count()) step();  // just after a Slow cycle
    pulse(io.ixReset, 19);  // T#19ms: over before the next Slow cycle
    step(40);
    CHECK(gvl.bJam);
    pulse(io.ixReset, 20);
    step();
    CHECK_FALSE(gvl.bJam);
  }
}

TEST_SUITE("FB_Conveyor") {
  // The block alone, called once per cycle by testing::cycles with an FB_DolMotor as its drive.
  struct ConveyorBlock {
    FB_Conveyor fb;
    FB_DolMotor motor;
    testing::cycles<FB_Conveyor&> run{fb, "T#1ms"_iec};

    ConveyorBlock() {
      fb.ipMotor = motor;
      fb.bStop = TRUE;
    }
  };

  TEST_CASE_FIXTURE(ConveyorBlock, "the latch, the drive called through I_Motor") {
    run.step();
    CHECK_FALSE(fb.bRunning);
    fb.bStart = TRUE;
    run.step();
    fb.bStart = FALSE;
    CHECK(fb.bRunning);
    CHECK(motor.bContactor);
    CHECK(fb.bAtSpeed);
    run.step(10);
    CHECK(fb.bRunning);
    run.pulse(fb.bStop, 1, FALSE);
    CHECK_FALSE(fb.bRunning);
    CHECK_FALSE(motor.bContactor);
    CHECK(fb.bStop);  // given back after the pulse
  }

  TEST_CASE_FIXTURE(ConveyorBlock, "the jam: TON tJam on bRunning AND bPartEye, T#2s to the cycle") {
    run.pulse(fb.bStart);
    run.force(fb.bPartEye, TRUE);
    run.step();
    CHECK(run.now() == LTIME("T#2ms"_iec));
    CHECK_FALSE(run.run_until(fb.bJam, "T#1s999ms"_iec));
    CHECK(run.run_until(fb.bJam, "T#1ms"_iec));
    CHECK(run.now() == LTIME("T#2s2ms"_iec));  // the cycle at T#2s1ms: T#2s after the one at T#1ms
    CHECK_FALSE(fb.bRunning);
    CHECK_FALSE(motor.bContactor);

    fb.Reset();  // ACTION Reset, with the part still there: the block itself does not check the eye
    CHECK_FALSE(fb.bJam);
    CHECK(fb.wParts == 0);
    run.step();
    CHECK_FALSE(fb.bJam);  // bRunning is FALSE: the timer does not run
    CHECK_FALSE(fb.bRunning);
  }

  TEST_CASE_FIXTURE(ConveyorBlock, "ctParts counts the eye's rising edges up to wBatchSize, and Reset clears it") {
    fb.wBatchSize = 2;
    run.pulse(fb.bPartEye, 3);
    run.step(3);
    CHECK(fb.wParts == 1);
    CHECK_FALSE(fb.bBatchDone);
    run.pulse(fb.bPartEye, 3);
    CHECK(fb.wParts == 2);
    CHECK(fb.bBatchDone);
    run.step(3);
    run.pulse(fb.bPartEye, 3);
    CHECK(fb.wParts == 3);  // counts on past the batch until reset
    CHECK(fb.bBatchDone);
    fb.Reset();
    CHECK(fb.wParts == 0);
    CHECK_FALSE(fb.bBatchDone);
  }

  TEST_CASE_FIXTURE(ConveyorBlock, "PROPERTY rSpeed: Get reads rSetpoint (50 %), Set clamps it to 20..100 %") {
    CHECK(fb.rSpeed == 50.0f);
    fb.rSpeed = 75.0f;
    CHECK(fb.rSpeed == 75.0f);
    CHECK(fb.rSetpoint == 75.0f);
    fb.rSpeed = 120.0f;
    CHECK(fb.rSpeed == 100.0f);
    fb.rSpeed = 19.9f;
    CHECK(fb.rSpeed == 20.0f);
    fb.rSpeed = -1.0f;
    CHECK(fb.rSpeed == 20.0f);
  }

  TEST_CASE("called with no drive assigned to ipMotor: a fault each cycle") {
    FB_Conveyor fb;
    testing::cycles run{[&] { fb("bStart"_ = TRUE, "bStop"_ = TRUE); }, "T#1ms"_iec};
    CHECK_FAULT(run.step(), fault_kind::unassigned_interface);
    testing::expect_faults faults;
    run.step(3);
    CHECK(faults.count() == 3);
    CHECK(faults.only(fault_kind::unassigned_interface));
    CHECK(faults.last().time == LTIME("T#3ms"_iec));
    CHECK(faults.last().task == nullptr);  // no application: no task
    CHECK(fb.bRunning);                    // the body ran up to the call of the drive
  }
}

TEST_SUITE("FB_VfdMotor") {
  TEST_CASE("ramps at 100 % per tRamp, up and down, enabled until it stands") {
    FB_VfdMotor vfd;
    vfd.tRamp = "T#200ms"_iec;
    BOOL bRun;
    BOOL bAtSpeed;
    testing::cycles run{[&] { bAtSpeed = vfd.Run({"bRun"_ = bRun, "rSetpoint"_ = 40.0f}); }, "T#10ms"_iec};
    run.step();  // at T#0ms: tLast := T#0ms
    bRun = TRUE;
    CHECK(run.run_until(bAtSpeed, "T#80ms"_iec));  // 40 % at 5 % per T#10ms: 8 cycles
    CHECK(run.now() == LTIME("T#90ms"_iec));
    CHECK(vfd.iSpeedRef == 6554);  // REAL_TO_INT(40 * 163.84)
    CHECK(vfd.rSpeed == 40.0f);
    bRun = FALSE;
    run.step();
    CHECK_FALSE(bAtSpeed);
    CHECK(vfd.bEnable);
    CHECK(vfd.rSpeed == 35.0f);
    CHECK(run.run_until([&] { return !vfd.bEnable; }, "T#70ms"_iec));
    CHECK(vfd.iSpeedRef == 0);
  }
}
