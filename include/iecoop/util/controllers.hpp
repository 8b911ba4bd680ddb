// SPDX-License-Identifier: MIT
// iecoop/util/controllers.hpp — the CODESYS Util library's controllers PD, PID and PID_FIXCYCLE.
//
//     fbPID(ACTUAL := rTemp, SET_POINT := 80.0, KP := 2.0, TN := 30.0, TV := 1.0,
//           Y_MIN := 0.0, Y_MAX := 100.0);
//     fbPID("ACTUAL"_ = rTemp, "SET_POINT"_ = REAL(80.0), "KP"_ = REAL(2.0), "TN"_ = REAL(30.0), "TV"_ = REAL(1.0),
//           "Y_MIN"_ = REAL(0.0), "Y_MAX"_ = REAL(100.0));
//     rHeater := fbPID.Y;                   rHeater = fbPID.Y;
//
// Y = KP * (e + 1/TN * integral of e dt + TV * de/dt) + Y_OFFSET, e = SET_POINT - ACTUAL, times
// in seconds (PD: no integral). PID and PD measure the time between two calls on the cycle
// clock in whole milliseconds (TIME), as CODESYS's do; PID_FIXCYCLE is told it (CYCLE, seconds).
// Each call, in REAL arithmetic and in this order (docs/util.md, "Controllers"; the closed-loop
// test tests/util/pid_scipy.py mirrors it operation by operation):
//   1. e := SET_POINT - ACTUAL.
//   2. The first call and every call with RESET: KP, TN and TV are taken (the parameters apply
//      only there and in manual mode, as documented), the integral := 0, OVERFLOW := FALSE, the
//      derivative's four values := e, Y := Y_OFFSET, LIMITS_ACTIVE := FALSE. Nothing else.
//   3. MANUAL: the parameters are taken, Y := Y_MANUAL, LIMITS_ACTIVE := FALSE, the four values
//      := e, and (PID) the integral := ((Y_MANUAL - Y_OFFSET) / KP - e) * TN, so that the switch
//      back to automatic is bumpless. Nothing else.
//   4. While OVERFLOW, nothing happens (Y keeps its value) until a RESET.
//   5. dt := the seconds since the last call (PID, PD: the milliseconds / 1000.0) or CYCLE; if
//      dt <= 0 (two calls in one millisecond, a CYCLE of 0), nothing else happens.
//   6. (PID) integral := integral + e * dt; beyond +-1E38, OVERFLOW := TRUE and nothing else.
//   7. d := (3.0 * (e - e3) + e1 - e2) / (10.0 * dt), DERIVATIVE's four-point slope.
//   8. y := KP * (e + integral / TN + TV * d) + Y_OFFSET (the integral term left out where TN = 0:
//      TN = 0 switches the I part off instead of dividing by zero).
//   9. Where Y_MIN < Y_MAX (Y_MIN = Y_MAX = 0: no limits), y is limited to Y_MIN..Y_MAX and
//      LIMITS_ACTIVE tells whether it was; while it is, (PID) the integral is set to what would
//      have given exactly the limit, ((y - Y_OFFSET) / KP - e - TV * d) * TN (the documented
//      anti-windup: "as if the input history had produced the limited value"). Y := y.
#pragma once

#include <cstdint>

#include <iecoop/config.hpp>
#include <iecoop/pou/call_interface.hpp>
#include <iecoop/pou/function_block.hpp>
#include <iecoop/pou/variables.hpp>
#include <iecoop/standard/cycle_clock.hpp>
#include <iecoop/types/elementary.hpp>
#include <iecoop/types/time.hpp>
#include <iecoop/util/mathematical_functions.hpp>

#include <iecoop/detail/push_macros.hpp>

namespace iecoop {

namespace detail {

/**
 * The state and the steps of PD (Integral false), PID and PID_FIXCYCLE (Integral true). A call
 * reads the block's inputs where a step needs them and writes its outputs (the block hands
 * their storage over), so that it costs what the steps cost.
 */
template <bool Integral>
class controller_core {
 public:
  /// One call of `block` (its ACTUAL, SET_POINT, KP, TN, TV, Y_MANUAL, Y_OFFSET, Y_MIN, Y_MAX,
  /// MANUAL, RESET): steps 1 to 9 of the header's list; the seconds since the last call from
  /// `clock` (restart() where the call ends before step 5, seconds() at step 5).
  // Inlined into the block's body, its one caller (Clang 14 and 16 would call it: 6 instructions
  // of a PID's 80 more per call).
  template <class Block, class Clock>
  [[gnu::always_inline]] void call(const Block& block, Clock& clock, REAL& y_out, BOOL& limits_out,
                                   BOOL& overflow_out) noexcept {
    const float e = static_cast<float>(block.SET_POINT) - static_cast<float>(block.ACTUAL);
    if (!started_ || block.RESET) {
      started_ = true;
      take_parameters(block);
      integral_ = 0.0F;
      overflow_out = FALSE;
      slope_.reset(e);
      y_out = block.Y_OFFSET;
      limits_out = FALSE;
      clock.restart();
      return;
    }
    if (block.MANUAL) {
      take_parameters(block);
      const float y_manual = block.Y_MANUAL;
      y_out = y_manual;
      limits_out = FALSE;
      slope_.reset(e);
      if constexpr (Integral) {
        if (kp_ != 0.0F && tn_ != 0.0F) {
          float a = y_manual - static_cast<float>(block.Y_OFFSET);
          a = a / kp_;
          a = a - e;
          set_integral(a * tn_, overflow_out);
        }
      }
      clock.restart();
      return;
    }
    if (overflow_out) return;
    const float dt = clock.seconds();
    if (!(dt > 0.0F)) return;
    if constexpr (Integral) {
      if (!integrate(integral_, e, dt)) {
        overflow_out = TRUE;
        return;
      }
    }
    const float d = slope_.next(e, dt);
    const float d_part = tv_ * d;
    float sum = e;
    if (Integral && tn_ != 0.0F) sum = sum + integral_ / tn_;
    sum = sum + d_part;
    const float y_offset = block.Y_OFFSET;
    float y = kp_ * sum;
    y = y + y_offset;
    bool limited = false;
    const float y_min = block.Y_MIN;
    const float y_max = block.Y_MAX;
    if (y_min < y_max) {
      if (y > y_max) {
        y = y_max;
        limited = true;
      } else if (y < y_min) {
        y = y_min;
        limited = true;
      }
    }
    if constexpr (Integral) {
      if (limited && kp_ != 0.0F && tn_ != 0.0F) {
        float a = y - y_offset;
        a = a / kp_;
        a = a - e;
        a = a - d_part;
        set_integral(a * tn_, overflow_out);
      }
    }
    y_out = y;
    limits_out = BOOL(limited);
  }

 private:
  template <class Block>
  void take_parameters(const Block& block) noexcept {
    kp_ = block.KP;
    if constexpr (Integral) tn_ = block.TN;
    tv_ = block.TV;
  }
  void set_integral(float value, BOOL& overflow_out) noexcept {
    if (value <= integral_limit && value >= -integral_limit) {
      integral_ = value;
    } else {
      overflow_out = TRUE;
    }
  }

  four_point_slope slope_;
  float integral_ = 0.0F;  // of e over the seconds
  float kp_ = 0.0F;        // the parameters taken at the start, a RESET or in manual mode
  float tn_ = 0.0F;
  float tv_ = 0.0F;
  bool started_ = false;
};

/// The seconds between two calls, on the cycle clock in whole milliseconds (PID, PD).
class call_interval {
 public:
  /// The next interval starts now.
  void restart() noexcept { last_ = cycle_clock::now_as<TIME>(); }
  /// Seconds since restart() or the last seconds(), as REAL: milliseconds / 1000.0.
  float seconds() noexcept {
    const TIME now = cycle_clock::now_as<TIME>();
    const auto ms = static_cast<std::uint32_t>(now.count() - last_.count());
    last_ = now;
    return seconds_of(ms);
  }

 private:
  TIME last_;
};

/// PID_FIXCYCLE's clock: the time it is told.
struct told_interval {
  float cycle;
  [[nodiscard]] float seconds() const noexcept { return cycle; }
  void restart() const noexcept {}
};

}  // namespace detail

/// FUNCTION_BLOCK PD: a PD controller that measures the time between its calls in ms.
class PD : public function_block<PD> {
 public:
  REAL ACTUAL;                        ///< VAR_INPUT: the actual value, the process variable
  REAL SET_POINT;                     ///< VAR_INPUT: the set point
  REAL KP;                            ///< VAR_INPUT: the proportional gain
  REAL TV;                            ///< VAR_INPUT: the derivative time in s (0: a P controller)
  REAL Y_MANUAL;                      ///< VAR_INPUT: Y while MANUAL
  REAL Y_OFFSET;                      ///< VAR_INPUT: the offset of Y
  REAL Y_MIN;                         ///< VAR_INPUT: the lower limit of Y (Y_MIN = Y_MAX = 0: none)
  REAL Y_MAX;                         ///< VAR_INPUT: the upper limit of Y
  BOOL MANUAL;                        ///< VAR_INPUT: TRUE: Y := Y_MANUAL
  BOOL RESET;                         ///< VAR_INPUT: TRUE: Y := Y_OFFSET, the controller restarts
  read_only<REAL, PD> Y;              ///< VAR_OUTPUT: the manipulated variable
  read_only<BOOL, PD> LIMITS_ACTIVE;  ///< VAR_OUTPUT: Y was limited to Y_MIN..Y_MAX

  using VAR_INPUT = pins<&PD::ACTUAL, &PD::SET_POINT, &PD::KP, &PD::TV, &PD::Y_MANUAL, &PD::Y_OFFSET, &PD::Y_MIN,
                         &PD::Y_MAX, &PD::MANUAL, &PD::RESET>;
  using VAR_OUTPUT = pins<&PD::Y, &PD::LIMITS_ACTIVE>;

 private:
  friend struct block_access;

  void body() noexcept {
    BOOL no_overflow;  // PD has no integral to overflow
    core_.call(*this, clock_, Y.ref(), LIMITS_ACTIVE.ref(), no_overflow);
  }

  detail::controller_core<false> core_;
  detail::call_interval clock_;
};

/// FUNCTION_BLOCK PID: a PID controller that measures the time between its calls in ms.
class PID : public function_block<PID> {
 public:
  REAL ACTUAL;                         ///< VAR_INPUT: the actual value, the process variable
  REAL SET_POINT;                      ///< VAR_INPUT: the set point
  REAL KP;                             ///< VAR_INPUT: the proportional gain
  REAL TN;                             ///< VAR_INPUT: the reset (integral) time in s (0: no I part)
  REAL TV;                             ///< VAR_INPUT: the derivative time in s
  REAL Y_MANUAL;                       ///< VAR_INPUT: Y while MANUAL
  REAL Y_OFFSET;                       ///< VAR_INPUT: the offset of Y
  REAL Y_MIN;                          ///< VAR_INPUT: the lower limit of Y (Y_MIN = Y_MAX = 0: none)
  REAL Y_MAX;                          ///< VAR_INPUT: the upper limit of Y
  BOOL MANUAL;                         ///< VAR_INPUT: TRUE: Y := Y_MANUAL
  BOOL RESET;                          ///< VAR_INPUT: TRUE: Y := Y_OFFSET, the integral := 0
  read_only<REAL, PID> Y;              ///< VAR_OUTPUT: the manipulated variable
  read_only<BOOL, PID> LIMITS_ACTIVE;  ///< VAR_OUTPUT: Y was limited to Y_MIN..Y_MAX
  read_only<BOOL, PID> OVERFLOW;       ///< VAR_OUTPUT: the integral overflowed; suspended until RESET

  using VAR_INPUT = pins<&PID::ACTUAL, &PID::SET_POINT, &PID::KP, &PID::TN, &PID::TV, &PID::Y_MANUAL, &PID::Y_OFFSET,
                         &PID::Y_MIN, &PID::Y_MAX, &PID::MANUAL, &PID::RESET>;
  using VAR_OUTPUT = pins<&PID::Y, &PID::LIMITS_ACTIVE, &PID::OVERFLOW>;

 private:
  friend struct block_access;

  void body() noexcept { core_.call(*this, clock_, Y.ref(), LIMITS_ACTIVE.ref(), OVERFLOW.ref()); }

  detail::controller_core<true> core_;
  detail::call_interval clock_;
};

/// FUNCTION_BLOCK PID_FIXCYCLE: PID with the time between two calls given (CYCLE, in s).
class PID_FIXCYCLE : public function_block<PID_FIXCYCLE> {
 public:
  REAL ACTUAL;                                  ///< VAR_INPUT: the actual value, the process variable
  REAL SET_POINT;                               ///< VAR_INPUT: the set point
  REAL KP;                                      ///< VAR_INPUT: the proportional gain
  REAL TN;                                      ///< VAR_INPUT: the reset (integral) time in s (0: no I part)
  REAL TV;                                      ///< VAR_INPUT: the derivative time in s
  REAL Y_MANUAL;                                ///< VAR_INPUT: Y while MANUAL
  REAL Y_OFFSET;                                ///< VAR_INPUT: the offset of Y
  REAL Y_MIN;                                   ///< VAR_INPUT: the lower limit of Y (Y_MIN = Y_MAX = 0: none)
  REAL Y_MAX;                                   ///< VAR_INPUT: the upper limit of Y
  BOOL MANUAL;                                  ///< VAR_INPUT: TRUE: Y := Y_MANUAL
  BOOL RESET;                                   ///< VAR_INPUT: TRUE: Y := Y_OFFSET, the integral := 0
  REAL CYCLE;                                   ///< VAR_INPUT: the time in s between two calls
  read_only<REAL, PID_FIXCYCLE> Y;              ///< VAR_OUTPUT: the manipulated variable
  read_only<BOOL, PID_FIXCYCLE> LIMITS_ACTIVE;  ///< VAR_OUTPUT: Y was limited to Y_MIN..Y_MAX
  read_only<BOOL, PID_FIXCYCLE> OVERFLOW;       ///< VAR_OUTPUT: the integral overflowed; suspended until RESET

  using VAR_INPUT = pins<&PID_FIXCYCLE::ACTUAL, &PID_FIXCYCLE::SET_POINT, &PID_FIXCYCLE::KP, &PID_FIXCYCLE::TN,
                         &PID_FIXCYCLE::TV, &PID_FIXCYCLE::Y_MANUAL, &PID_FIXCYCLE::Y_OFFSET, &PID_FIXCYCLE::Y_MIN,
                         &PID_FIXCYCLE::Y_MAX, &PID_FIXCYCLE::MANUAL, &PID_FIXCYCLE::RESET, &PID_FIXCYCLE::CYCLE>;
  using VAR_OUTPUT = pins<&PID_FIXCYCLE::Y, &PID_FIXCYCLE::LIMITS_ACTIVE, &PID_FIXCYCLE::OVERFLOW>;

 private:
  friend struct block_access;

  void body() noexcept {
    detail::told_interval clock{CYCLE};
    core_.call(*this, clock, Y.ref(), LIMITS_ACTIVE.ref(), OVERFLOW.ref());
  }

  detail::controller_core<true> core_;
};

}  // namespace iecoop

#include <iecoop/detail/pop_macros.hpp>
