// What the SFC benchmarks run (sfc_bench.cpp, sfc_count.cpp): one batch sequence of 20 steps
// written as an SFC chart (sfc::chart, codesys scan order) and as the switch-based state machine
// an embedded engineer writes by hand for the same behaviour, driven by the same inputs.
//
//   INIT -> FILL -> HEAT =(simultaneous divergence)=> MIX1 .. MIX5 | DOSE1 .. DOSE4
//        =(simultaneous convergence)=> COOL -> DRAIN1 -> DRAIN2 -> RINSE -> DRY -> CHECK -> PACK
//        -> DONE -> INIT
//
// Actions: 15 ACTIONs qualified N, one S/R pair of ACTIONs (A_PUMP: set in HEAT, reset in
// COOL), three L ACTIONs (A_BOOST, A_DOSE2, A_RINSE), one N BOOL variable (VALVE_MIX) and three
// S/R BOOL variables (MOTOR, DOSING, VALVE_OUT); each ACTION counts the scans its body runs in.
// Transitions on inputs and on step times. Scan k runs at k x 10 ms with the inputs of
// `inputs_at(k)`, which take the chart through the whole sequence every 40 to 60 scans.
//
// Both sides produce the same outputs after every scan (`same_outputs`): the counters show the
// codesys order's final scans (an ACTION's body runs once more in the scan after its Q fell), the
// BOOL variables follow Q without one. `check()` compares them scan by scan.
#pragma once

#include <cstdint>

#include <iecoop/iecoop.hpp>

namespace sfc_programs {

using namespace iecoop;
using namespace iecoop::literals;

/// The scan period: scan k runs at k x scan_period_ms.
inline constexpr std::uint32_t scan_period_ms = 10;

/// The inputs of one scan.
struct inputs {
  bool START, LEVEL_HI, SENSOR_A, SENSOR_B, JOIN_OK, LEVEL_LO, OK;
};

/// The inputs of scan k: patterns of different periods, so that every transition fires, at
/// varying points of the sequence.
constexpr inputs inputs_at(std::uint32_t k) noexcept {
  return {k % 16 != 15, k % 3 == 0, k % 4 == 1, k % 5 == 2, k % 2 == 0, k % 3 == 1, k % 6 != 5};
}

// PROGRAM P_BATCH (Engine: none, the default engine; sfc::general_engine for the general one)
template <class... Engine>
struct P_BATCH_ON : program<P_BATCH_ON<Engine...>> {
  // VAR_INPUT
  BOOL START, LEVEL_HI, SENSOR_A, SENSOR_B, JOIN_OK, LEVEL_LO, OK;
  // VAR_OUTPUT: BOOL variables as actions
  BOOL MOTOR, VALVE_MIX, DOSING, VALVE_OUT;
  // VAR: how many scans each ACTION's body ran in
  DINT C_IDLE, C_FILL, C_HEAT, C_BOOST, C_PUMP, C_MIX1, C_MIX3, C_MIX5, C_DOSE1, C_DOSE2, C_DOSE4, C_COOL, C_DRAIN,
      C_DRAIN2, C_RINSE, C_DRY, C_CHECK, C_PACK, C_DONE;
  // END_VAR
  sfc::step INIT, FILL, HEAT, MIX1, MIX2, MIX3, MIX4, MIX5, DOSE1, DOSE2, DOSE3, DOSE4, COOL, DRAIN1, DRAIN2, RINSE,
      DRY, CHECK, PACK, DONE;

  // TRANSITIONs as named objects (CODESYS): member functions returning BOOL
  BOOL T_HEAT_DONE() { return HEAT.T >= "T#50ms"_iec; }
  BOOL T_MIX1_DONE() { return MIX1.T >= "T#20ms"_iec; }
  BOOL T_MIX3_DONE() { return MIX3.T >= "T#30ms"_iec; }
  BOOL T_NOT_SENSOR_A() { return !SENSOR_A; }
  BOOL T_DOSE2_DONE() { return DOSE2.T >= "T#40ms"_iec; }
  BOOL T_COOL_DONE() { return COOL.T >= "T#40ms"_iec; }
  BOOL T_DRAIN2_DONE() { return DRAIN2.T >= "T#20ms"_iec; }
  BOOL T_RINSE_DONE() { return RINSE.T >= "T#50ms"_iec; }
  BOOL T_DRY_DONE() { return DRY.T >= "T#30ms"_iec; }
  BOOL T_PACK_DONE() { return PACK.T >= "T#20ms"_iec; }
  BOOL T_NOT_START() { return !START; }

  void A_IDLE() { C_IDLE = C_IDLE + 1; }
  void A_FILL() { C_FILL = C_FILL + 1; }
  void A_HEAT() { C_HEAT = C_HEAT + 1; }
  void A_BOOST() { C_BOOST = C_BOOST + 1; }
  void A_PUMP() { C_PUMP = C_PUMP + 1; }
  void A_MIX1() { C_MIX1 = C_MIX1 + 1; }
  void A_MIX3() { C_MIX3 = C_MIX3 + 1; }
  void A_MIX5() { C_MIX5 = C_MIX5 + 1; }
  void A_DOSE1() { C_DOSE1 = C_DOSE1 + 1; }
  void A_DOSE2() { C_DOSE2 = C_DOSE2 + 1; }
  void A_DOSE4() { C_DOSE4 = C_DOSE4 + 1; }
  void A_COOL() { C_COOL = C_COOL + 1; }
  void A_DRAIN() { C_DRAIN = C_DRAIN + 1; }
  void A_DRAIN2() { C_DRAIN2 = C_DRAIN2 + 1; }
  void A_RINSE() { C_RINSE = C_RINSE + 1; }
  void A_DRY() { C_DRY = C_DRY + 1; }
  void A_CHECK() { C_CHECK = C_CHECK + 1; }
  void A_PACK() { C_PACK = C_PACK + 1; }
  void A_DONE() { C_DONE = C_DONE + 1; }

  using P = P_BATCH_ON;
  // clang-format off: one chart element a line, as textual SFC writes them
  sfc::chart<
      P, sfc::codesys, Engine..., sfc::INITIAL_STEP<&P::INIT, sfc::N<&P::A_IDLE>>,
      sfc::TRANSITION<sfc::FROM<&P::INIT>, sfc::TO<&P::FILL>, &P::START>,
      sfc::STEP<&P::FILL, sfc::N<&P::A_FILL>, sfc::S<&P::MOTOR>>,
      sfc::TRANSITION<sfc::FROM<&P::FILL>, sfc::TO<&P::HEAT>, &P::LEVEL_HI>,
      sfc::STEP<&P::HEAT, sfc::N<&P::A_HEAT>, sfc::L<&P::A_BOOST, "T#30ms">, sfc::S<&P::A_PUMP>>,
      sfc::TRANSITION<sfc::FROM<&P::HEAT>, sfc::TO<&P::MIX1, &P::DOSE1>, &P::T_HEAT_DONE>,  // divergence
      // branch MIX
      sfc::STEP<&P::MIX1, sfc::N<&P::A_MIX1>>, sfc::TRANSITION<sfc::FROM<&P::MIX1>, sfc::TO<&P::MIX2>, &P::T_MIX1_DONE>,
      sfc::STEP<&P::MIX2, sfc::N<&P::VALVE_MIX>>, sfc::TRANSITION<sfc::FROM<&P::MIX2>, sfc::TO<&P::MIX3>, &P::SENSOR_A>,
      sfc::STEP<&P::MIX3, sfc::N<&P::A_MIX3>>, sfc::TRANSITION<sfc::FROM<&P::MIX3>, sfc::TO<&P::MIX4>, &P::T_MIX3_DONE>,
      sfc::STEP<&P::MIX4>, sfc::TRANSITION<sfc::FROM<&P::MIX4>, sfc::TO<&P::MIX5>, &P::T_NOT_SENSOR_A>,
      sfc::STEP<&P::MIX5, sfc::N<&P::A_MIX5>>,
      // branch DOSE
      sfc::STEP<&P::DOSE1, sfc::N<&P::A_DOSE1>, sfc::S<&P::DOSING>>,
      sfc::TRANSITION<sfc::FROM<&P::DOSE1>, sfc::TO<&P::DOSE2>, &P::SENSOR_B>,
      sfc::STEP<&P::DOSE2, sfc::L<&P::A_DOSE2, "T#20ms">>,
      sfc::TRANSITION<sfc::FROM<&P::DOSE2>, sfc::TO<&P::DOSE3>, &P::T_DOSE2_DONE>,
      sfc::STEP<&P::DOSE3, sfc::R<&P::DOSING>>, sfc::TRANSITION<sfc::FROM<&P::DOSE3>, sfc::TO<&P::DOSE4>, &P::SENSOR_B>,
      sfc::STEP<&P::DOSE4, sfc::N<&P::A_DOSE4>>,
      sfc::TRANSITION<sfc::FROM<&P::MIX5, &P::DOSE4>, sfc::TO<&P::COOL>, &P::JOIN_OK>,  // convergence
      sfc::STEP<&P::COOL, sfc::N<&P::A_COOL>, sfc::R<&P::A_PUMP>>,
      sfc::TRANSITION<sfc::FROM<&P::COOL>, sfc::TO<&P::DRAIN1>, &P::T_COOL_DONE>,
      sfc::STEP<&P::DRAIN1, sfc::N<&P::A_DRAIN>, sfc::S<&P::VALVE_OUT>>,
      sfc::TRANSITION<sfc::FROM<&P::DRAIN1>, sfc::TO<&P::DRAIN2>, &P::LEVEL_LO>,
      sfc::STEP<&P::DRAIN2, sfc::N<&P::A_DRAIN2>>,
      sfc::TRANSITION<sfc::FROM<&P::DRAIN2>, sfc::TO<&P::RINSE>, &P::T_DRAIN2_DONE>,
      sfc::STEP<&P::RINSE, sfc::L<&P::A_RINSE, "T#30ms">>,
      sfc::TRANSITION<sfc::FROM<&P::RINSE>, sfc::TO<&P::DRY>, &P::T_RINSE_DONE>,
      sfc::STEP<&P::DRY, sfc::N<&P::A_DRY>, sfc::R<&P::MOTOR>>,
      sfc::TRANSITION<sfc::FROM<&P::DRY>, sfc::TO<&P::CHECK>, &P::T_DRY_DONE>,
      sfc::STEP<&P::CHECK, sfc::N<&P::A_CHECK>>, sfc::TRANSITION<sfc::FROM<&P::CHECK>, sfc::TO<&P::PACK>, &P::OK>,
      sfc::STEP<&P::PACK, sfc::N<&P::A_PACK>, sfc::R<&P::VALVE_OUT>>,
      sfc::TRANSITION<sfc::FROM<&P::PACK>, sfc::TO<&P::DONE>, &P::T_PACK_DONE>, sfc::STEP<&P::DONE, sfc::N<&P::A_DONE>>,
      sfc::TRANSITION<sfc::FROM<&P::DONE>, sfc::TO<&P::INIT>, &P::T_NOT_START>>
      chart;
  // clang-format on

  void body() { chart(*this); }
};
// END_PROGRAM
using P_BATCH = P_BATCH_ON<>;                             // the default engine (compiled, at -O2/-O3)
using P_BATCH_GENERAL = P_BATCH_ON<sfc::general_engine>;  // the general engine

/// The cycle clock at scan k (k x scan_period_ms), as a task sets it before its cycle: both
/// sides read their time from it.
inline void set_clock(std::uint32_t k) noexcept {
  cycle_clock::set(LTIME::from_ticks(static_cast<std::uint64_t>(k) * scan_period_ms * 1'000'000U));
}

/// Scan k of the chart: the cycle clock and the inputs, then the program.
template <class P>
inline void chart_scan(P& p, std::uint32_t k) noexcept {
  set_clock(k);
  const inputs in = inputs_at(k);
  p.START = in.START;
  p.LEVEL_HI = in.LEVEL_HI;
  p.SENSOR_A = in.SENSOR_A;
  p.SENSOR_B = in.SENSOR_B;
  p.JOIN_OK = in.JOIN_OK;
  p.LEVEL_LO = in.LEVEL_LO;
  p.OK = in.OK;
  p();
}

// --- The same sequence, hand-written -------------------------------------------------------------

/// The sequence as a careful engineer writes it without SFC: a switch on the main sequence's
/// step and, while the two branches run, one on each branch's step; the steps a transition
/// reaches start in the next scan, as in the chart; the ACTIONs whose step was left run once
/// more then (`left_*`); a stored action is a bool; an L action remembers whether it ran.
struct hand_batch {
  enum class main_step : std::uint8_t {
    INIT,
    FILL,
    HEAT,
    BRANCHES,
    COOL,
    DRAIN1,
    DRAIN2,
    RINSE,
    DRY,
    CHECK,
    PACK,
    DONE,
    NONE
  };
  enum class mix_step : std::uint8_t { MIX1, MIX2, MIX3, MIX4, MIX5, NONE };
  enum class dose_step : std::uint8_t { DOSE1, DOSE2, DOSE3, DOSE4, NONE };

  // inputs
  bool START, LEVEL_HI, SENSOR_A, SENSOR_B, JOIN_OK, LEVEL_LO, OK;
  // outputs
  bool MOTOR, VALVE_MIX, DOSING, VALVE_OUT;
  std::int32_t C_IDLE, C_FILL, C_HEAT, C_BOOST, C_PUMP, C_MIX1, C_MIX3, C_MIX5, C_DOSE1, C_DOSE2, C_DOSE4, C_COOL,
      C_DRAIN, C_DRAIN2, C_RINSE, C_DRY, C_CHECK, C_PACK, C_DONE;
  // state
  main_step main = main_step::INIT;
  mix_step mix = mix_step::NONE;
  dose_step dose = dose_step::NONE;
  main_step left_main = main_step::NONE;  // left in the last scan: its N actions' final scan
  mix_step left_mix = mix_step::NONE;
  dose_step left_dose = dose_step::NONE;
  bool main_entered = true, mix_entered, dose_entered;  // the step's time starts in this scan
  bool pump, boost_q, dose2_q, rinse_q;
  std::uint32_t main_t0, mix_t0, dose_t0;  // ms: when the step became active

  void go(main_step s) noexcept {
    left_main = main;
    main = s;
    main_entered = true;
  }
  void go(mix_step s) noexcept {
    left_mix = mix;
    mix = s;
    mix_entered = true;
  }
  void go(dose_step s) noexcept {
    left_dose = dose;
    dose = s;
    dose_entered = true;
  }

  // An L action: runs while its step's time is below the limit, and once more (final scan).
  static void limited(bool active, bool& q, std::int32_t& counter) noexcept {
    if (active) {
      ++counter;
      q = true;
    } else if (q) {
      ++counter;
      q = false;
    }
  }

  void scan(std::uint32_t now) noexcept {
    if (main_entered) {
      main_t0 = now;
      main_entered = false;
    }
    if (mix_entered) {
      mix_t0 = now;
      mix_entered = false;
    }
    if (dose_entered) {
      dose_t0 = now;
      dose_entered = false;
    }
    final_scans();

    const std::uint32_t t = now - main_t0;
    switch (main) {
      case main_step::INIT:
        ++C_IDLE;
        if (START) go(main_step::FILL);
        break;
      case main_step::FILL:
        ++C_FILL;
        MOTOR = true;
        if (LEVEL_HI) go(main_step::HEAT);
        break;
      case main_step::HEAT:
        ++C_HEAT;
        limited(t < 30, boost_q, C_BOOST);
        pump = true;
        if (t >= 50) {
          go(main_step::BRANCHES);
          go(mix_step::MIX1);
          go(dose_step::DOSE1);
        }
        break;
      case main_step::BRANCHES: {
        const bool join = mix == mix_step::MIX5 && dose == dose_step::DOSE4 && JOIN_OK;
        branch_mix(now);
        branch_dose(now);
        if (join) {
          go(mix_step::NONE);
          go(dose_step::NONE);
          go(main_step::COOL);
        }
        break;
      }
      case main_step::COOL:
        ++C_COOL;
        if (pump) {  // R: the stored action's final scan
          pump = false;
          ++C_PUMP;
        }
        if (t >= 40) go(main_step::DRAIN1);
        break;
      case main_step::DRAIN1:
        ++C_DRAIN;
        VALVE_OUT = true;
        if (LEVEL_LO) go(main_step::DRAIN2);
        break;
      case main_step::DRAIN2:
        ++C_DRAIN2;
        if (t >= 20) go(main_step::RINSE);
        break;
      case main_step::RINSE:
        limited(t < 30, rinse_q, C_RINSE);
        if (t >= 50) go(main_step::DRY);
        break;
      case main_step::DRY:
        ++C_DRY;
        MOTOR = false;
        if (t >= 30) go(main_step::CHECK);
        break;
      case main_step::CHECK:
        ++C_CHECK;
        if (OK) go(main_step::PACK);
        break;
      case main_step::PACK:
        ++C_PACK;
        VALVE_OUT = false;
        if (t >= 20) go(main_step::DONE);
        break;
      case main_step::DONE:
        ++C_DONE;
        if (!START) go(main_step::INIT);
        break;
      case main_step::NONE: break;
    }
    if (pump) ++C_PUMP;
  }

  void branch_mix(std::uint32_t now) noexcept {
    const std::uint32_t t = now - mix_t0;
    switch (mix) {
      case mix_step::MIX1:
        ++C_MIX1;
        if (t >= 20) go(mix_step::MIX2);
        break;
      case mix_step::MIX2:
        VALVE_MIX = true;
        if (SENSOR_A) go(mix_step::MIX3);
        break;
      case mix_step::MIX3:
        ++C_MIX3;
        if (t >= 30) go(mix_step::MIX4);
        break;
      case mix_step::MIX4:
        if (!SENSOR_A) go(mix_step::MIX5);
        break;
      case mix_step::MIX5: ++C_MIX5; break;
      case mix_step::NONE: break;
    }
  }

  void branch_dose(std::uint32_t now) noexcept {
    const std::uint32_t t = now - dose_t0;
    switch (dose) {
      case dose_step::DOSE1:
        ++C_DOSE1;
        DOSING = true;
        if (SENSOR_B) go(dose_step::DOSE2);
        break;
      case dose_step::DOSE2:
        limited(t < 20, dose2_q, C_DOSE2);
        if (t >= 40) go(dose_step::DOSE3);
        break;
      case dose_step::DOSE3:
        DOSING = false;
        if (SENSOR_B) go(dose_step::DOSE4);
        break;
      case dose_step::DOSE4: ++C_DOSE4; break;
      case dose_step::NONE: break;
    }
  }

  // The scan after a step was left: its N actions run once more, an N variable falls.
  void final_scans() noexcept {
    switch (left_main) {
      case main_step::INIT: ++C_IDLE; break;
      case main_step::FILL: ++C_FILL; break;
      case main_step::HEAT:
        ++C_HEAT;
        limited(false, boost_q, C_BOOST);
        break;
      case main_step::COOL: ++C_COOL; break;
      case main_step::DRAIN1: ++C_DRAIN; break;
      case main_step::DRAIN2: ++C_DRAIN2; break;
      case main_step::RINSE: limited(false, rinse_q, C_RINSE); break;
      case main_step::DRY: ++C_DRY; break;
      case main_step::CHECK: ++C_CHECK; break;
      case main_step::PACK: ++C_PACK; break;
      case main_step::DONE: ++C_DONE; break;
      case main_step::BRANCHES:
      case main_step::NONE: break;
    }
    left_main = main_step::NONE;
    switch (left_mix) {
      case mix_step::MIX1: ++C_MIX1; break;
      case mix_step::MIX2: VALVE_MIX = false; break;
      case mix_step::MIX3: ++C_MIX3; break;
      case mix_step::MIX5: ++C_MIX5; break;
      case mix_step::MIX4:
      case mix_step::NONE: break;
    }
    left_mix = mix_step::NONE;
    switch (left_dose) {
      case dose_step::DOSE1: ++C_DOSE1; break;
      case dose_step::DOSE2: limited(false, dose2_q, C_DOSE2); break;
      case dose_step::DOSE4: ++C_DOSE4; break;
      case dose_step::DOSE3:
      case dose_step::NONE: break;
    }
    left_dose = dose_step::NONE;
  }
};

/// Scan k of the hand-written machine: the cycle clock and the inputs, then the machine, which
/// reads the cycle's time stamp in milliseconds (TIME) as a program of a task does.
inline void hand_scan(hand_batch& h, std::uint32_t k) noexcept {
  set_clock(k);
  const inputs in = inputs_at(k);
  h.START = in.START;
  h.LEVEL_HI = in.LEVEL_HI;
  h.SENSOR_A = in.SENSOR_A;
  h.SENSOR_B = in.SENSOR_B;
  h.JOIN_OK = in.JOIN_OK;
  h.LEVEL_LO = in.LEVEL_LO;
  h.OK = in.OK;
  h.scan(cycle_clock::now_as<TIME>().count());
}

// --- Checks -------------------------------------------------------------------------------------

/// The outputs after a scan: the 19 counters and the 4 BOOL variables.
struct outputs {
  std::int32_t counters[19];
  bool bools[4];
  friend bool operator==(const outputs&, const outputs&) = default;
};

template <class... E>
inline outputs outputs_of(const P_BATCH_ON<E...>& p) noexcept {
  return {{p.C_IDLE.value(), p.C_FILL.value(), p.C_HEAT.value(), p.C_BOOST.value(), p.C_PUMP.value(), p.C_MIX1.value(),
           p.C_MIX3.value(), p.C_MIX5.value(), p.C_DOSE1.value(), p.C_DOSE2.value(), p.C_DOSE4.value(),
           p.C_COOL.value(), p.C_DRAIN.value(), p.C_DRAIN2.value(), p.C_RINSE.value(), p.C_DRY.value(),
           p.C_CHECK.value(), p.C_PACK.value(), p.C_DONE.value()},
          {bool(p.MOTOR), bool(p.VALVE_MIX), bool(p.DOSING), bool(p.VALVE_OUT)}};
}

inline outputs outputs_of(const hand_batch& h) noexcept {
  return {{h.C_IDLE, h.C_FILL, h.C_HEAT, h.C_BOOST, h.C_PUMP, h.C_MIX1, h.C_MIX3, h.C_MIX5, h.C_DOSE1, h.C_DOSE2,
           h.C_DOSE4, h.C_COOL, h.C_DRAIN, h.C_DRAIN2, h.C_RINSE, h.C_DRY, h.C_CHECK, h.C_PACK, h.C_DONE},
          {h.MOTOR, h.VALVE_MIX, h.DOSING, h.VALVE_OUT}};
}

/// The number of scans `check` compares.
inline constexpr std::uint32_t check_scans = 1000;

/// Runs the chart on the engine of P (P_BATCH or P_BATCH_GENERAL) and the hand-written machine
/// for `check_scans` scans from their initial state and returns the first scan after which their
/// outputs differ, or check_scans if none does; `sequences` gets the number of times the chart
/// reached DONE (so that the check covers the whole sequence, many times).
template <class P = P_BATCH>
inline std::uint32_t check(std::uint32_t& sequences) noexcept {
  P p;
  hand_batch h{};
  sequences = 0;
  bool done = false;
  for (std::uint32_t k = 0; k < check_scans; ++k) {
    chart_scan(p, k);
    hand_scan(h, k);
    if (!(outputs_of(p) == outputs_of(h))) return k;
    if (p.DONE.X && !done) ++sequences;
    done = p.DONE.X;
  }
  return check_scans;
}

/// A figure of the outputs, which the kernels return so that the optimiser keeps every scan.
inline std::uint32_t checksum(const outputs& o) noexcept {
  std::uint32_t sum = 0;
  for (const std::int32_t c : o.counters) sum = sum * 31U + static_cast<std::uint32_t>(c);
  for (const bool b : o.bools) sum = sum * 2U + (b ? 1U : 0U);
  return sum;
}

// Makes the compiler assume that memory was read and written here (as benchmark::ClobberMemory).
inline void barrier() { asm volatile("" ::: "memory"); }

/// n scans of the chart (on the engine of P).
template <class P = P_BATCH>
inline std::uint32_t chart_scans(std::uint64_t n) {
  P p;
  for (std::uint64_t i = 0; i < n; ++i) {
    chart_scan(p, static_cast<std::uint32_t>(i));
    barrier();
  }
  return checksum(outputs_of(p));
}

/// n scans of the hand-written machine.
inline std::uint32_t hand_scans(std::uint64_t n) {
  hand_batch h{};
  for (std::uint64_t i = 0; i < n; ++i) {
    hand_scan(h, static_cast<std::uint32_t>(i));
    barrier();
  }
  return checksum(outputs_of(h));
}

}  // namespace sfc_programs
