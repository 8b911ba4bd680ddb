// The iecoop demo's machine: the PLC application (its types, global variables, blocks,
// programs and task configuration), written as a PLC engineer would write it in CODESYS,
// with the Structured Text beside each line of C++, and the simulation it runs against.
// demo.cpp runs it and prints what happens; tests/programs/demo_heap.cpp runs the same
// application to show that it never allocates after start-up.
//
// The machine is a conveyor that carries parts to a box. A photo eye at the belt's end sees
// each part go by; the PLC counts the parts in batches, and stops the belt when a part stays
// in front of the eye for longer than T#2s (a jam). The belt is driven either by a motor on a
// contactor (direct on-line, one speed) or by a frequency inverter (ramps and a speed
// reference): both behind one INTERFACE, chosen by a PERSISTENT setting.
//
//   POUs        INTERFACE I_Motor; FUNCTION_BLOCK FB_DolMotor, FB_VfdMotor IMPLEMENTS I_Motor;
//               FUNCTION_BLOCK FB_Conveyor (RS start/stop latch, TON jam timeout, CTU part
//               counter, PROPERTY rSpeed, ACTION Reset); PROGRAM IO_PRG, SUPERVISION_PRG
//   Globals     GVL_IO (located I/O), GVL (between the tasks), GVL_Config (PERSISTENT)
//   Tasks       Fast  cyclic T#1ms   priority 0  watchdog T#2ms x 2    IO_PRG
//               Slow  cyclic T#20ms  priority 5  watchdog T#15ms x 2   SUPERVISION_PRG
//
// The operator and the belt itself are simulated by a third task, Sim, whose programs play a
// script against the simulated field (simulated_io) and record a trace of the key signals.
// Because the simulation is a task of the application, the same code runs in simulated time
// (the default: 21 s of machine time in a fraction of a second, the same every run) and, with
// --realtime, against the wall clock on iecoop's real-time runner (demo.cpp, which prints the
// trace and the tasks' statistics; `iecoop_demo --help` lists its options).
#pragma once

#include <iecoop/iecoop.hpp>

#include <algorithm>
#include <array>
#include <cstddef>
#include <cstdint>
#include <span>

namespace demo {

using namespace iecoop;

// TYPE E_Motor : (DOL := 0, VFD := 1) INT; END_TYPE
enum class E_Motor : std::int16_t { DOL = 0, VFD = 1 };

// ---------------------------------------------------------------------------------------
// Global variables

// VAR_GLOBAL                          (GVL_IO: the I/O map)
struct GVL_IO : global_variables<GVL_IO> {
  [[no_unique_address]] located<BOOL, "%IX0.0"> ixStart;    // ixStart AT %IX0.0 : BOOL;    (* START, normally open *)
  [[no_unique_address]] located<BOOL, "%IX0.1"> ixStop;     // ixStop AT %IX0.1 : BOOL;     (* STOP, normally closed *)
  [[no_unique_address]] located<BOOL, "%IX0.2"> ixPartEye;  // ixPartEye AT %IX0.2 : BOOL;  (* photo eye, TRUE: blocked *)
  [[no_unique_address]] located<BOOL, "%IX0.3"> ixReset;    // ixReset AT %IX0.3 : BOOL;    (* RESET, normally open *)
  [[no_unique_address]] located<INT, "%IW1"> iwSpeed;       // iwSpeed AT %IW1 : INT;       (* speed setpoint, 0..100 % *)
  [[no_unique_address]] located<BOOL, "%QX0.0"> qxMotor;    // qxMotor AT %QX0.0 : BOOL;    (* contactor or drive enable *)
  [[no_unique_address]] located<BOOL, "%QX0.1"> qxJamLamp;  // qxJamLamp AT %QX0.1 : BOOL;  (* jam lamp *)
  [[no_unique_address]] located<INT, "%QW1"> qwSpeedRef;    // qwSpeedRef AT %QW1 : INT;    (* 16#4000 = 100 % *)
  // END_VAR
  // The located variables, which the application checks at compile time: no two share a bit.
  using LOCATED = pins<&GVL_IO::ixStart, &GVL_IO::ixStop, &GVL_IO::ixPartEye, &GVL_IO::ixReset, &GVL_IO::iwSpeed,
                       &GVL_IO::qxMotor, &GVL_IO::qxJamLamp, &GVL_IO::qwSpeedRef>;
};

// VAR_GLOBAL                          (GVL: between the tasks; each variable has one writer)
struct GVL : global_variables<GVL> {
  BOOL bRunning;       // bRunning : BOOL;        (* written by IO_PRG ... *)
  BOOL bAtSpeed;       // bAtSpeed : BOOL;
  BOOL bJam;           // bJam : BOOL;
  BOOL bBatchDone;     // bBatchDone : BOOL;
  WORD wParts;         // wParts : WORD;
  REAL rSpeed;         // rSpeed : REAL;
  BOOL bResetRequest;  // bResetRequest : BOOL;   (* ... and by SUPERVISION_PRG *)
  // END_VAR
};

// VAR_GLOBAL PERSISTENT               (GVL_Config: set at commissioning, kept over resets and downloads)
struct GVL_Config : global_variables<GVL_Config> {
  persistent<E_Motor> eMotor{E_Motor::VFD};  // eMotor : E_Motor := E_Motor.VFD;   (* the drive fitted *)
  persistent<WORD> wBatchSize{8};            // wBatchSize : WORD := 8;            (* parts per box *)
  // END_VAR
};

// ---------------------------------------------------------------------------------------
// The motor, behind an interface

// INTERFACE I_Motor
struct I_Motor : interface_base<I_Motor> {
  // METHOD Run : BOOL                (* call it every cycle; TRUE while the motor turns at the speed asked for *)
  struct Run_vars {  // VAR_INPUT
    BOOL bRun;       //     bRun : BOOL;          (* run command *)
    REAL rSetpoint;  //     rSetpoint : REAL;     (* speed, % of nominal *)
  };                 // END_VAR
  virtual BOOL Run(args<Run_vars> in) = 0;

  // PROPERTY rSpeed : REAL           (* Get only: the speed now, % of nominal *)
  virtual REAL rSpeed_Get() = 0;
  [[no_unique_address]] property<REAL, &I_Motor::rSpeed_Get> rSpeed{this};
};

// FUNCTION_BLOCK FB_DolMotor IMPLEMENTS I_Motor      (* direct on-line: a contactor, one speed *)
struct FB_DolMotor : function_block<FB_DolMotor, implements<I_Motor>> {
  BOOL bContactor;  // VAR_OUTPUT bContactor : BOOL; END_VAR
  using VAR_OUTPUT = pins<&FB_DolMotor::bContactor>;

  // METHOD Run : BOOL
  BOOL Run(args<Run_vars> in) override {
    bContactor = in.bRun;  // bContactor := bRun;   (* rSetpoint means nothing to it *)
    return bContactor;     // Run := bContactor;
  }
  // PROPERTY rSpeed : REAL (Get)
  REAL rSpeed_Get() override {
    return SEL(bContactor, 0.0f, 100.0f);  // rSpeed := SEL(bContactor, 0.0, 100.0);
  }
};

// FUNCTION_BLOCK FB_VfdMotor IMPLEMENTS I_Motor      (* frequency inverter: ramps, speed reference *)
struct FB_VfdMotor : function_block<FB_VfdMotor, implements<I_Motor>> {
  TIME tRamp = "T#1s"_iec;  // VAR_INPUT tRamp : TIME := T#1s; END_VAR     (* 0 to 100 %, and back *)
  BOOL bEnable;             // VAR_OUTPUT bEnable : BOOL;                  (* drive enable *)
  INT iSpeedRef;            //            iSpeedRef : INT; END_VAR         (* 16#4000 = 100 % (PROFIdrive N2) *)
  var<REAL> rRamp;          // VAR rRamp : REAL;                           (* the ramped speed, % *)
  var<TIME> tLast;          //     tLast : TIME; END_VAR                   (* TIME() at the last call *)
  using VAR_INPUT = pins<&FB_VfdMotor::tRamp>;
  using VAR_OUTPUT = pins<&FB_VfdMotor::bEnable, &FB_VfdMotor::iSpeedRef>;

  // METHOD Run : BOOL
  // VAR tNow : TIME; rStep, rTarget : REAL; END_VAR
  BOOL Run(args<Run_vars> in) override {
    const TIME tNow = TIME(system_time);                               // tNow := TIME();
    const REAL rStep = 100.0f * TIME_TO_REAL(tNow - tLast)             // rStep := 100.0 * TIME_TO_REAL(tNow - tLast)
                       / TIME_TO_REAL(tRamp);                          //          / TIME_TO_REAL(tRamp);
    tLast = tNow;                                                      // tLast := tNow;
    const REAL rTarget = SEL(in.bRun, 0.0f, in.rSetpoint);             // rTarget := SEL(bRun, 0.0, rSetpoint);
    if (rRamp < rTarget) {                                             // IF rRamp < rTarget THEN
      rRamp = MIN(rRamp + rStep, rTarget);                             //     rRamp := MIN(rRamp + rStep, rTarget);
    } else if (rRamp > rTarget) {                                      // ELSIF rRamp > rTarget THEN
      rRamp = MAX(rRamp - rStep, rTarget);                             //     rRamp := MAX(rRamp - rStep, rTarget);
    }                                                                  // END_IF
    bEnable = in.bRun | (rRamp > 0.0f);                                // bEnable := bRun OR rRamp > 0.0;  (* until stopped *)
    iSpeedRef = REAL_TO_INT(rRamp * 163.84f);                          // iSpeedRef := REAL_TO_INT(rRamp * 163.84);
    return in.bRun & (rRamp == rTarget);                               // Run := bRun AND rRamp = rTarget;
  }
  // PROPERTY rSpeed : REAL (Get)
  REAL rSpeed_Get() override { return rRamp; }  // rSpeed := rRamp;
};

// ---------------------------------------------------------------------------------------
// The conveyor

// FUNCTION_BLOCK FB_Conveyor
struct FB_Conveyor : function_block<FB_Conveyor> {
  BOOL bStart;                 // VAR_INPUT  bStart : BOOL;           (* START, normally open *)
  BOOL bStop;                  //            bStop : BOOL;            (* STOP, normally closed *)
  BOOL bPartEye;               //            bPartEye : BOOL;         (* photo eye at the belt's end *)
  WORD wBatchSize = 8;         //            wBatchSize : WORD := 8;
  itf<I_Motor> ipMotor;        //            ipMotor : I_Motor;       (* whichever drive is fitted *)
  BOOL bRunning;               // VAR_OUTPUT bRunning : BOOL;         (* the belt is told to run ... *)
  BOOL bAtSpeed;               //            bAtSpeed : BOOL;         (* ... and turns at the speed asked for *)
  BOOL bJam;                   //            bJam : BOOL;             (* latched until Reset *)
  BOOL bBatchDone;             //            bBatchDone : BOOL;       (* wBatchSize parts counted *)
  WORD wParts;                 //            wParts : WORD;           (* parts counted since the last Reset *)
  RS fbRunLatch;               // VAR        fbRunLatch : RS;         (* start/stop latch, stop dominant *)
  TON tJam;                    //            tJam : TON;              (* jam timeout *)
  CTU ctParts;                 //            ctParts : CTU;           (* part counter *)
  var<REAL> rSetpoint{50.0f};  //            rSetpoint : REAL := 50;  (* behind PROPERTY rSpeed *)
  static constexpr TIME tJamTime = "T#2s"_iec;  // VAR CONSTANT tJamTime : TIME := T#2s;
  static constexpr REAL rMinSpeed = 20.0f;      //              rMinSpeed : REAL := 20;  (* slower: a part is a jam *)
  static constexpr REAL rMaxSpeed = 100.0f;     //              rMaxSpeed : REAL := 100; END_VAR
  using VAR_INPUT = pins<&FB_Conveyor::bStart, &FB_Conveyor::bStop, &FB_Conveyor::bPartEye, &FB_Conveyor::wBatchSize,
                         &FB_Conveyor::ipMotor>;
  using VAR_OUTPUT = pins<&FB_Conveyor::bRunning, &FB_Conveyor::bAtSpeed, &FB_Conveyor::bJam, &FB_Conveyor::bBatchDone,
                          &FB_Conveyor::wParts>;

  void body() {
    tJam("IN"_ = bRunning & bPartEye, "PT"_ = tJamTime);             // tJam(IN := bRunning AND bPartEye, PT := tJamTime);
    if (tJam.Q) {                                                    // IF tJam.Q THEN
      bJam = TRUE;                                                   //     bJam := TRUE;
    }                                                                // END_IF
    ctParts("CU"_ = bPartEye, "RESET"_ = FALSE, "PV"_ = wBatchSize);  // ctParts(CU := bPartEye, RESET := FALSE,
                                                                     //         PV := wBatchSize);
    wParts = ctParts.CV;                                             // wParts := ctParts.CV;
    bBatchDone = ctParts.Q;                                          // bBatchDone := ctParts.Q;
    fbRunLatch("S"_ = bStart & !bJam,                                // fbRunLatch(S := bStart AND NOT bJam,
               "R1"_ = (!bStop) | bJam);                             //            R1 := NOT bStop OR bJam);
    bRunning = fbRunLatch.Q1;                                        // bRunning := fbRunLatch.Q1;
    bAtSpeed = ipMotor->Run({"bRun"_ = bRunning,                     // bAtSpeed := ipMotor.Run(bRun := bRunning,
                             "rSetpoint"_ = rSetpoint});             //                         rSetpoint := rSetpoint);
  }

  // ACTION Reset                     (* acknowledges a jam and counts from 0 again *)
  void Reset() {
    bJam = FALSE;              // bJam := FALSE;
    ctParts("RESET"_ = TRUE);  // ctParts(RESET := TRUE);
    wParts = ctParts.CV;       // wParts := ctParts.CV;
    bBatchDone = ctParts.Q;    // bBatchDone := ctParts.Q;
  }

  // PROPERTY rSpeed : REAL           (* the speed setpoint, % of nominal *)
  REAL rSpeed_Get() { return rSetpoint; }  // Get: rSpeed := rSetpoint;
  void rSpeed_Set(REAL value) {                  // Set:
    rSetpoint = LIMIT(rMinSpeed, value, rMaxSpeed);  // rSetpoint := LIMIT(rMinSpeed, rSpeed, rMaxSpeed);
  }
  [[no_unique_address]] property<REAL, &FB_Conveyor::rSpeed_Get, &FB_Conveyor::rSpeed_Set> rSpeed{this};
};

// ---------------------------------------------------------------------------------------
// The programs

// PROGRAM IO_PRG                     (* task Fast: the drive chosen, the conveyor, the outputs *)
struct IO_PRG : program<IO_PRG> {
  FB_Conveyor fbConveyor;  // VAR fbConveyor : FB_Conveyor;
  FB_DolMotor fbDol;       //     fbDol : FB_DolMotor;
  FB_VfdMotor fbVfd;       //     fbVfd : FB_VfdMotor;
  itf<I_Motor> ipMotor;    //     ipMotor : I_Motor;
  R_TRIG rtReset;          //     rtReset : R_TRIG; END_VAR

  void body() {
    GVL_IO& io = GVL_IO::instance();
    GVL& gvl = GVL::instance();
    const GVL_Config& config = GVL_Config::instance();

    switch (config.eMotor) {                            // CASE GVL_Config.eMotor OF   (* the drive fitted *)
      case E_Motor::DOL: ipMotor = fbDol; break;        // E_Motor.DOL: ipMotor := fbDol;
      case E_Motor::VFD: ipMotor = fbVfd; break;        // E_Motor.VFD: ipMotor := fbVfd;
    }                                                   // END_CASE

    rtReset("CLK"_ = gvl.bResetRequest);                // rtReset(CLK := GVL.bResetRequest);   (* from task Slow *)
    if (rtReset.Q) {                                    // IF rtReset.Q THEN
      fbConveyor.Reset();                               //     fbConveyor.Reset();
    }                                                   // END_IF

    fbConveyor.rSpeed = INT_TO_REAL(io.iwSpeed);        // fbConveyor.rSpeed := INT_TO_REAL(GVL_IO.iwSpeed);  (* Set clamps *)
    fbConveyor("bStart"_ = io.ixStart,                  // fbConveyor(bStart := GVL_IO.ixStart,
               "bStop"_ = io.ixStop,                    //            bStop := GVL_IO.ixStop,
               "bPartEye"_ = io.ixPartEye,              //            bPartEye := GVL_IO.ixPartEye,
               "wBatchSize"_ = config.wBatchSize,       //            wBatchSize := GVL_Config.wBatchSize,
               "ipMotor"_ = ipMotor);                   //            ipMotor := ipMotor);

    switch (config.eMotor) {                            // CASE GVL_Config.eMotor OF   (* each drive has its own wiring *)
      case E_Motor::DOL:                                // E_Motor.DOL:
        io.qxMotor = fbDol.bContactor;                  //     GVL_IO.qxMotor := fbDol.bContactor;
        io.qwSpeedRef = 0;                              //     GVL_IO.qwSpeedRef := 0;
        break;
      case E_Motor::VFD:                                // E_Motor.VFD:
        io.qxMotor = fbVfd.bEnable;                     //     GVL_IO.qxMotor := fbVfd.bEnable;
        io.qwSpeedRef = fbVfd.iSpeedRef;                //     GVL_IO.qwSpeedRef := fbVfd.iSpeedRef;
        break;
    }                                                   // END_CASE
    io.qxJamLamp = fbConveyor.bJam;                     // GVL_IO.qxJamLamp := fbConveyor.bJam;

    gvl.bRunning = fbConveyor.bRunning;                 // GVL.bRunning := fbConveyor.bRunning;
    gvl.bAtSpeed = fbConveyor.bAtSpeed;                 // GVL.bAtSpeed := fbConveyor.bAtSpeed;
    gvl.bJam = fbConveyor.bJam;                         // GVL.bJam := fbConveyor.bJam;
    gvl.bBatchDone = fbConveyor.bBatchDone;             // GVL.bBatchDone := fbConveyor.bBatchDone;
    gvl.wParts = fbConveyor.wParts;                     // GVL.wParts := fbConveyor.wParts;
    gvl.rSpeed = ipMotor->rSpeed;                       // GVL.rSpeed := ipMotor.rSpeed;
  }
};

// PROGRAM SUPERVISION_PRG            (* task Slow: the counters, batches, the jam's acknowledgement *)
struct SUPERVISION_PRG : program<SUPERVISION_PRG> {
  retain<UDINT> udiParts;     // VAR RETAIN udiParts : UDINT;     (* parts through the eye, ever *)
  retain<UDINT> udiBatches;   //            udiBatches : UDINT;   (* complete batches *)
  retain<UDINT> udiRejected;  //            udiRejected : UDINT;  (* parts of batches a jam interrupted *)
  retain<UINT> uiJams;        //            uiJams : UINT; END_VAR
  var<WORD> wPartsSeen;       // VAR        wPartsSeen : WORD;    (* GVL.wParts in the last cycle *)
  R_TRIG rtJam;               //            rtJam : R_TRIG;
  R_TRIG rtBatch;             //            rtBatch : R_TRIG;
  R_TRIG rtReset;             //            rtReset : R_TRIG; END_VAR

  void body() {
    GVL_IO& io = GVL_IO::instance();
    GVL& gvl = GVL::instance();

    // The parts counted since the last cycle: the counter only counts up, and after a reset
    // every part it shows is new.
    if (gvl.wParts >= wPartsSeen) {                           // IF GVL.wParts >= wPartsSeen THEN
      udiParts += WORD_TO_UDINT(gvl.wParts - wPartsSeen);     //     udiParts := udiParts + WORD_TO_UDINT(GVL.wParts
                                                              //                                          - wPartsSeen);
    } else {                                                  // ELSE
      udiParts += WORD_TO_UDINT(gvl.wParts);                  //     udiParts := udiParts + WORD_TO_UDINT(GVL.wParts);
    }                                                         // END_IF
    wPartsSeen = gvl.wParts;                                  // wPartsSeen := GVL.wParts;

    rtJam("CLK"_ = gvl.bJam);                                 // rtJam(CLK := GVL.bJam);
    if (rtJam.Q) {                                            // IF rtJam.Q THEN
      uiJams += 1U;                                           //     uiJams := uiJams + 1;
    }                                                         // END_IF

    gvl.bResetRequest = FALSE;                                // GVL.bResetRequest := FALSE;   (* a request lasts one cycle *)
    rtBatch("CLK"_ = gvl.bBatchDone);                         // rtBatch(CLK := GVL.bBatchDone);
    rtReset("CLK"_ = io.ixReset);                             // rtReset(CLK := GVL_IO.ixReset);
    if (rtBatch.Q) {                                          // IF rtBatch.Q THEN   (* the box is full: on to the next *)
      udiBatches += 1U;                                       //     udiBatches := udiBatches + 1;
      gvl.bResetRequest = TRUE;                               //     GVL.bResetRequest := TRUE;
    } else if (rtReset.Q & gvl.bJam & !io.ixPartEye) {        // ELSIF rtReset.Q AND GVL.bJam AND NOT GVL_IO.ixPartEye THEN
      udiRejected += WORD_TO_UDINT(gvl.wParts);               //     udiRejected := udiRejected + WORD_TO_UDINT(GVL.wParts);
      gvl.bResetRequest = TRUE;                               //     GVL.bResetRequest := TRUE;   (* the box is rejected *)
    }                                                         // END_IF   (* RESET with the part still at the eye: nothing *)
  }
};

}  // namespace demo

// ---------------------------------------------------------------------------------------
// The simulation: the operator, the belt with its parts, and a trace recorder. This is not
// PLC code: it stands for the world outside the PLC, which a test bench would provide. It
// runs as a task of its own (Sim, every millisecond, before the PLC's tasks), so that the
// same script plays in simulated time and in real time.
namespace sim {

using namespace iecoop;
using demo::E_Motor;

inline simulated_io<> field{window_of<"%IB0", 4>};  // the PLC's terminals, %IB0..%IB3, as the field sees them
inline E_Motor fitted = E_Motor::VFD;  // the drive actually wired to the belt

// What happened in this millisecond, for the trace ("operator: START, motor on").
inline STRING<60> events;
inline void event(const STRING<60>& what) { events = events == "" ? what : STRING<60>(CONCAT(events, ", ", what)); }

// PROGRAM BELT_SIM: the belt follows the drive's outputs, carries the parts, and the photo
// eye sees them. Parts 8 cm long travel at up to 0.5 m/s towards the eye, 1 m from the
// infeed; a feeder puts one on the belt every 25 cm of travel; parts held up by a jammed one
// queue behind it, 5 cm apart; a part whose tail is 10 cm past the eye drops into the box.
struct BELT_SIM : program<BELT_SIM> {
  static constexpr double belt_speed = 0.5;  // m/s at 100 %
  static constexpr double eye_at = 1.0;      // m from the infeed
  static constexpr double part_length = 0.08;
  static constexpr double pitch = 0.25;
  static constexpr double queue_gap = 0.05;
  static constexpr double box_at = eye_at + 0.10;

  struct part {
    double front = 0.0;  // m from the infeed
    bool stuck = false;
  };
  // The parts on the belt, the one nearest the eye first: parts[0] to parts[count - 1]. In
  // the program's own memory, as a PLC would keep them: the instances are built at start()
  // and again at every reset, and a std::vector would allocate each time. About ten parts
  // fit between the infeed and the box.
  std::array<part, 32> parts{};
  std::size_t count = 0;
  bool jam_next = false;  // the next part to reach the eye sticks there
  double fed = 0.0;       // belt travel since the feeder's last part
  LTIME last{};

  BELT_SIM() {
    for (double front = 0.9; front > 0.0; front -= pitch) add({front, false});
  }

  void jam_next_part() { jam_next = true; }
  void remove_stuck_part() {
    remove_if([](const part& p) { return p.stuck; });
  }

  void body() {
    const LTIME now = cycle_clock::now();
    const double dt = static_cast<double>((now - last).count()) / 1e9;
    last = now;
    double percent = 0.0;
    if (field.get<BOOL, "%QX0.0">()) {
      percent = fitted == E_Motor::DOL ? 100.0 : field.get<INT, "%QW1">().value() / 163.84;
    }
    const double dx = belt_speed * percent / 100.0 * dt;

    for (std::size_t i = 0; i < count; ++i) {
      part& p = parts[i];
      if (p.stuck) continue;
      double to = p.front + dx;
      if (i > 0) to = std::min(to, parts[i - 1].front - part_length - queue_gap);  // queue behind
      if (jam_next && p.front < eye_at + 0.02 && to >= eye_at + 0.02) {
        to = eye_at + 0.02;  // caught at the eye
        p.stuck = true;
        jam_next = false;
      }
      p.front = std::max(p.front, to);
    }
    remove_if([](const part& p) { return p.front - part_length >= box_at; });

    fed += dx;
    if (fed >= pitch && (count == 0 || parts[count - 1].front >= pitch)) {
      add({fed - pitch, false});
      fed = 0.0;
    }

    bool blocked = false;
    for (const part& p : std::span(parts.data(), count)) {
      blocked = blocked || (p.front >= eye_at && p.front - part_length < eye_at);
    }
    field.set<"%IX0.2">(BOOL(blocked));
  }

 private:
  void add(const part& p) {
    if (count < parts.size()) parts[count++] = p;
  }
  template <class Predicate>
  void remove_if(Predicate gone) {
    const auto end = std::remove_if(parts.begin(), parts.begin() + static_cast<std::ptrdiff_t>(count), gone);
    count = static_cast<std::size_t>(end - parts.begin());
  }
};

// PROGRAM OPERATOR_SIM: the operator's script, against the time on the cycle clock. A button
// is held for T#200ms.
enum class act : std::uint8_t { speed, start, stop, reset, jam, clear };
struct step {
  TIME at;
  act what = act::speed;
  INT value;
  const char* text = "";
};

inline std::span<const step> script() {
  static constexpr step steps[] = {
      {"T#0ms"_iec, act::speed, 60, "power on, speed 60 %"},
      {"T#500ms"_iec, act::start, 0, "operator: START"},
      {"T#3s"_iec, act::speed, 100, "operator: speed 100 %"},
      {"T#4s500ms"_iec, act::stop, 0, "operator: STOP"},
      {"T#6s"_iec, act::start, 0, "operator: START"},
      {"T#8s"_iec, act::jam, 0, "a part jams at the eye"},
      {"T#11s"_iec, act::reset, 0, "operator: RESET"},
      {"T#11s500ms"_iec, act::clear, 0, "part removed by hand"},
      {"T#12s"_iec, act::reset, 0, "operator: RESET"},
      {"T#12s500ms"_iec, act::speed, 10, "operator: speed 10 %"},
      {"T#13s"_iec, act::start, 0, "operator: START"},
      {"T#16s500ms"_iec, act::speed, 80, "operator: speed 80 %"},
      {"T#19s500ms"_iec, act::stop, 0, "operator: STOP"},
  };
  return steps;
}
inline constexpr TIME scenario_length = "T#21s"_iec;

struct OPERATOR_SIM : program<OPERATOR_SIM> {
  std::size_t next = 0;  // the next step of the script
  INT iSpeed;
  TP tpStart, tpStop, tpReset;

  void body() {
    BOOL bStart, bStop, bReset;
    const auto steps = script();
    for (; next < steps.size() && steps[next].at <= cycle_clock::now_as<TIME>(); ++next) {
      const step& s = steps[next];
      switch (s.what) {
        case act::speed: iSpeed = s.value; break;
        case act::start: bStart = TRUE; break;
        case act::stop: bStop = TRUE; break;
        case act::reset: bReset = TRUE; break;
        case act::jam: BELT_SIM::instance().jam_next_part(); break;
        case act::clear: BELT_SIM::instance().remove_stuck_part(); break;
      }
      event(s.text);
    }
    tpStart("IN"_ = bStart, "PT"_ = "T#200ms"_iec);
    tpStop("IN"_ = bStop, "PT"_ = "T#200ms"_iec);
    tpReset("IN"_ = bReset, "PT"_ = "T#200ms"_iec);
    field.set<"%IX0.0">(tpStart.Q);
    field.set<"%IX0.1">(!tpStop.Q);  // normally closed
    field.set<"%IX0.3">(tpReset.Q);
    field.set<"%IW1">(iSpeed);
  }
};

// One line of the trace.
struct row {
  LTIME time;
  BOOL start, stop, eye, reset;
  INT setpoint;
  BOOL motor, lamp;
  INT reference;
  REAL speed;
  WORD parts;
  UDINT total;
  STRING<60> events;
};

// PROGRAM TRACE_PRG: samples the field and the PLC's variables after the operator and the
// belt, and records a line when something happened or a key signal changed (CODESYS's
// trace, with a trigger on every change). main() prints the lines between runs.
struct TRACE_PRG : program<TRACE_PRG> {
  std::array<row, 256> rows{};
  std::size_t written = 0;
  std::size_t read = 0;
  std::size_t lost = 0;

  void body() {
    const demo::GVL& gvl = demo::GVL::instance();
    const demo::SUPERVISION_PRG& supervision = demo::SUPERVISION_PRG::instance();
    row r{};
    r.time = cycle_clock::now();
    r.start = field.get<BOOL, "%IX0.0">();
    r.stop = field.get<BOOL, "%IX0.1">();
    r.eye = field.get<BOOL, "%IX0.2">();
    r.reset = field.get<BOOL, "%IX0.3">();
    r.setpoint = field.get<INT, "%IW1">();
    r.motor = field.get<BOOL, "%QX0.0">();
    r.lamp = field.get<BOOL, "%QX0.1">();
    r.reference = field.get<INT, "%QW1">();
    r.speed = gvl.rSpeed;
    r.parts = gvl.wParts;
    r.total = supervision.udiParts;

    if (written > 0) {
      if (r.motor != last_.motor) event(r.motor ? "motor on" : "motor off");
      if (gvl.bAtSpeed & !bAtSpeed_) event("at speed");
      if (r.lamp != last_.lamp) event(r.lamp ? "JAM" : "jam cleared");
      if (r.parts > last_.parts) event("part counted");
      if (r.parts < last_.parts) event("counter reset");
      if (supervision.udiBatches != udiBatches_) event(CONCAT("batch ", UDINT_TO_STRING(supervision.udiBatches), " complete"));
    }
    bAtSpeed_ = gvl.bAtSpeed;
    udiBatches_ = supervision.udiBatches;
    if (written == 0 || events != "") {
      r.events = events;
      push(r);
    }
    events = "";
    last_ = r;
  }

 private:
  row last_{};
  BOOL bAtSpeed_;
  UDINT udiBatches_;

  void push(const row& r) {
    if (written - read == rows.size()) {
      ++lost;  // main() has not printed them yet
      return;
    }
    rows[written % rows.size()] = r;
    ++written;
  }
};

// Execution times for the simulation: IO_PRG 200..300 us, SUPERVISION_PRG 3..4.6 ms per cycle
// (varying from cycle to cycle); the simulation's own programs take none.
inline LTIME fast_cost(std::uint64_t n, void*) { return LTIME::from_ticks(200'000U + (n * 37U % 11U) * 10'000U); }
inline LTIME slow_cost(std::uint64_t n, void*) { return LTIME::from_ticks(3'000'000U + (n * 7U % 5U) * 400'000U); }

}  // namespace sim

// ---------------------------------------------------------------------------------------
// The application

namespace demo {

// The task configuration and the global variable lists. The application owns one instance
// of each program and list, and checks at compile time that no located variables overlap.
// Applications are neither copied nor moved: the caller's variable is this prvalue itself
// (`auto plc = demo::make_conveyor();`), which it then connects to sim::field.
inline auto make_conveyor() {
  using sim::BELT_SIM;
  using sim::OPERATOR_SIM;
  using sim::TRACE_PRG;
  return application{
      task<OPERATOR_SIM, BELT_SIM, TRACE_PRG>{"Sim", cyclic{"T#1ms"_iec}, 0},
      task<IO_PRG>{"Fast", cyclic{"T#1ms"_iec}, 0, watchdog{"T#2ms"_iec, 2}},
      task<SUPERVISION_PRG>{"Slow", cyclic{"T#20ms"_iec}, 5, watchdog{"T#15ms"_iec, 2}},
      globals<GVL_IO, GVL, GVL_Config>{},
  };
}

}  // namespace demo
