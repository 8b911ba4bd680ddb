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

/// What a controller is given in one call (its inputs, as floats).
struct controller_inputs {
  float actual;
  float set_point;
  float kp;
  float tn;
  float tv;
  float y_manual;
  float y_offset;
  float y_min;
  float y_max;
  bool manual;
  bool reset;
};

/// What a controller writes.
struct controller_outputs {
  float y;
  bool limits_active;
  bool overflow;
};

/// The state and the steps of PD (Integral false), PID and PID_FIXCYCLE (Integral true).
template <bool Integral>
class controller_core {
 public:
  /// Steps 1 to 4 of the header's list; TRUE if the call goes on to step 5.
  bool begin(const controller_inputs& in, controller_outputs& out) noexcept {
    error_ = in.set_point - in.actual;
    if (!started_ || in.reset) {
      started_ = true;
      take_parameters(in);
      integral_ = 0.0F;
      out.overflow = false;
      slope_.reset(error_);
      out.y = in.y_offset;
      out.limits_active = false;
      return false;
    }
    if (in.manual) {
      take_parameters(in);
      out.y = in.y_manual;
      out.limits_active = false;
      slope_.reset(error_);
      if constexpr (Integral) {
        if (kp_ != 0.0F && tn_ != 0.0F) {
          float a = in.y_manual - in.y_offset;
          a = a / kp_;
          a = a - error_;
          set_integral(a * tn_, out);
        }
      }
      return false;
    }
    return !out.overflow;
  }

  /// One call: steps 1 to 9, the time since the last call from `clock` (seconds(), and
  /// restart() where the call ends before step 5).
  template <class Clock>
  void call(const controller_inputs& in, Clock& clock, controller_outputs& out) noexcept {
    if (begin(in, out)) {
      step(in, clock.seconds(), out);
    } else {
      clock.restart();
    }
  }

  /// Steps 5 to 9, `dt` seconds after the last call.
  void step(const controller_inputs& in, float dt, controller_outputs& out) noexcept {
    if (!(dt > 0.0F)) return;
    if constexpr (Integral) {
      if (!integrate(integral_, error_, dt)) {
        out.overflow = true;
        return;
      }
    }
    const float d = slope_.next(error_, dt);
    const float d_part = tv_ * d;
    float sum = error_;
    if (Integral && tn_ != 0.0F) sum = sum + integral_ / tn_;
    sum = sum + d_part;
    float y = kp_ * sum;
    y = y + in.y_offset;
    bool limited = false;
    if (in.y_min < in.y_max) {
      if (y > in.y_max) {
        y = in.y_max;
        limited = true;
      } else if (y < in.y_min) {
        y = in.y_min;
        limited = true;
      }
    }
    if constexpr (Integral) {
      if (limited && kp_ != 0.0F && tn_ != 0.0F) {
        float a = y - in.y_offset;
        a = a / kp_;
        a = a - error_;
        a = a - d_part;
        set_integral(a * tn_, out);
      }
    }
    out.y = y;
    out.limits_active = limited;
  }

 private:
  void take_parameters(const controller_inputs& in) noexcept {
    kp_ = in.kp;
    tn_ = in.tn;
    tv_ = in.tv;
  }
  void set_integral(float value, controller_outputs& out) noexcept {
    if (value <= integral_limit && value >= -integral_limit) {
      integral_ = value;
    } else {
      out.overflow = true;
    }
  }

  four_point_slope slope_;
  float integral_ = 0.0F;  // of e over the seconds
  float error_ = 0.0F;
  float kp_ = 0.0F;  // the parameters taken at the start, a RESET or in manual mode
  float tn_ = 0.0F;
  float tv_ = 0.0F;
  bool started_ = false;
};

/// The milliseconds since the last call, on the cycle clock.
class call_interval {
 public:
  /// Seconds since the last call (0 on the first), as REAL: milliseconds / 1000.0.
  float seconds() noexcept {
    const TIME now = cycle_clock::now_as<TIME>();
    const std::uint32_t ms = timed_ ? static_cast<std::uint32_t>((now - last_).count()) : 0U;
    last_ = now;
    timed_ = true;
    return seconds_of(ms);
  }
  /// The next interval starts now.
  void restart() noexcept {
    last_ = cycle_clock::now_as<TIME>();
    timed_ = true;
  }

 private:
  TIME last_;
  bool timed_ = false;
};

/// PID_FIXCYCLE's clock: the time it is told.
struct told_interval {
  float cycle;
  [[nodiscard]] float seconds() const noexcept { return cycle; }
  void restart() const noexcept {}
};

/// A controller block's inputs (PD has no TN: 0, no integral).
template <class Block>
[[nodiscard]] controller_inputs inputs_of(const Block& b) noexcept {
  float tn = 0.0F;
  if constexpr (requires { b.TN; }) tn = b.TN;
  return controller_inputs{b.ACTUAL,
                           b.SET_POINT,
                           b.KP,
                           tn,
                           b.TV,
                           b.Y_MANUAL,
                           b.Y_OFFSET,
                           b.Y_MIN,
                           b.Y_MAX,
                           static_cast<bool>(b.MANUAL),
                           static_cast<bool>(b.RESET)};
}

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
    detail::controller_outputs out{Y.get(), static_cast<bool>(LIMITS_ACTIVE.get()), false};
    core_.call(detail::inputs_of(*this), clock_, out);
    Y = out.y;
    LIMITS_ACTIVE = BOOL(out.limits_active);
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

  void body() noexcept {
    detail::controller_outputs out{Y.get(), static_cast<bool>(LIMITS_ACTIVE.get()), static_cast<bool>(OVERFLOW.get())};
    core_.call(detail::inputs_of(*this), clock_, out);
    Y = out.y;
    LIMITS_ACTIVE = BOOL(out.limits_active);
    OVERFLOW = BOOL(out.overflow);
  }

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
    detail::controller_outputs out{Y.get(), static_cast<bool>(LIMITS_ACTIVE.get()), static_cast<bool>(OVERFLOW.get())};
    detail::told_interval clock{CYCLE};
    core_.call(detail::inputs_of(*this), clock, out);
    Y = out.y;
    LIMITS_ACTIVE = BOOL(out.limits_active);
    OVERFLOW = BOOL(out.overflow);
  }

  detail::controller_core<true> core_;
};

}  // namespace iecoop

#include <iecoop/detail/pop_macros.hpp>
