// SPDX-License-Identifier: MIT
// iecoop/util/mathematical_functions.hpp — the CODESYS Util library's mathematical blocks:
// DERIVATIVE, INTEGRAL, LIN_TRAFO, STATISTICS_INT, STATISTICS_REAL and VARIANCE.
//
//     fbDer(IN := rLevel, TM := 10);        fbDer("IN"_ = rLevel, "TM"_ = DWORD(10));   (* 10 ms since the last call *)
//     fbInt(IN := rFlow, TM := 10);         fbInt("IN"_ = rFlow, "TM"_ = DWORD(10));
//     fbTrafo(IN := rVolt, IN_MIN := 0, IN_MAX := 10, OUT_MIN := -20, OUT_MAX := 40);
//     fbStat(IN := iValue);                 fbStat("IN"_ = iValue);    (* MN, MX, AVG *)
//
// DERIVATIVE and INTEGRAL are told the time since their last call (TM, milliseconds, a DWORD),
// as documented; they read no clock. They compute in REAL, in this order (dt = TM / 1000.0, the
// seconds, so that a derivative is per second and an integral is IN x seconds):
//   DERIVATIVE  OUT := (3.0 * (IN - X3) + X1 - X2) / (10.0 * dt); X3 := X2; X2 := X1; X1 := IN
//               the slope of the least-squares line through the last four values (X1 the
//               value of the last call, X3 of three calls ago), exact for a straight line;
//   INTEGRAL    OUT := OUT + IN * dt (the sum of the parts IN x TM, as documented).
// A call with TM = 0 changes nothing (no time passed: no slope and no area; the documentation
// leaves it open). RESET: DERIVATIVE's OUT := 0 and its four values := IN; INTEGRAL's OUT := 0
// and OVERFLOW := FALSE. Before the first RESET the saved values are 0. INTEGRAL's OVERFLOW
// becomes TRUE when |OUT| exceeds 1E38 (REAL's range is 3.4E38) and then blocks it until RESET.
//
// LIN_TRAFO: OUT := OUT_MIN + (IN - IN_MIN) * (OUT_MAX - OUT_MIN) / (IN_MAX - IN_MIN); ERROR
// when IN_MIN = IN_MAX (OUT keeps its value) or IN lies outside IN_MIN..IN_MAX (OUT is the line
// extended). STATISTICS_*: MN, MX and AVG (the mean) of the values since the start or the last
// RESET; a call with RESET TRUE resets (AVG 0, MN the largest and MX the smallest value of the
// type) and its IN is not counted; STATISTICS_INT's mean truncates toward zero. VARIANCE: the
// variance of the values since the last RESET, over n (the population's: 0 after one value).
#pragma once

#include <cstdint>
#include <limits>
#include <type_traits>

#include <iecoop/config.hpp>
#include <iecoop/detail/constant_division.hpp>
#include <iecoop/pou/call_interface.hpp>
#include <iecoop/pou/function_block.hpp>
#include <iecoop/pou/variables.hpp>
#include <iecoop/types/elementary.hpp>

#include <iecoop/detail/push_macros.hpp>

namespace iecoop {

namespace detail {

/// DERIVATIVE's arithmetic, which PD and PID share: the slope through four values `dt` seconds apart.
struct four_point_slope {
  float x1 = 0.0F;  // the value of the last call
  float x2 = 0.0F;
  float x3 = 0.0F;  // three calls ago

  void reset(float value) noexcept { x1 = x2 = x3 = value; }
  /// The slope with `value` as the newest point; the points move on.
  [[nodiscard]] float next(float value, float dt) noexcept {
    const float difference = value - x3;
    const float weighted = 3.0F * difference;
    const float sum = weighted + x1;
    const float numerator = sum - x2;
    const float denominator = 10.0F * dt;
    x3 = x2;
    x2 = x1;
    x1 = value;
    return numerator / denominator;
  }
};

/// INTEGRAL's overflow limit: |OUT| beyond it is an overflow.
inline constexpr float integral_limit = 1e38F;

/// One step of INTEGRAL's sum: FALSE (and `sum` unchanged) on an overflow.
[[nodiscard]] inline bool integrate(float& sum, float value, float dt) noexcept {
  const float part = value * dt;
  const float next = sum + part;
  if (!(next <= integral_limit && next >= -integral_limit)) return false;  // also NaN
  sum = next;
  return true;
}

/// TM (milliseconds) as seconds: TM / 1000.0 in REAL.
[[nodiscard]] inline float seconds_of(std::uint32_t milliseconds) noexcept {
  return static_cast<float>(milliseconds) / 1000.0F;
}

}  // namespace detail

/// FUNCTION_BLOCK DERIVATIVE: the derivative of IN per second, from its last four values.
class DERIVATIVE : public function_block<DERIVATIVE> {
 public:
  REAL IN;                          ///< VAR_INPUT: the value
  DWORD TM;                         ///< VAR_INPUT: the time since the last call, in ms
  BOOL RESET;                       ///< VAR_INPUT: OUT := 0, the saved values := IN
  read_only<REAL, DERIVATIVE> OUT;  ///< VAR_OUTPUT: the derivative

  using VAR_INPUT = pins<&DERIVATIVE::IN, &DERIVATIVE::TM, &DERIVATIVE::RESET>;
  using VAR_OUTPUT = pins<&DERIVATIVE::OUT>;

 private:
  friend struct iecoop::block_access;

  void body() noexcept {
    if (RESET) {
      OUT = REAL(0.0F);
      points_.reset(IN);
      return;
    }
    if (TM.value() == 0U) return;
    OUT = points_.next(IN, detail::seconds_of(TM.value()));
  }

  detail::four_point_slope points_;
};

/// FUNCTION_BLOCK INTEGRAL: the integral of IN over the seconds, summed call by call.
class INTEGRAL : public function_block<INTEGRAL> {
 public:
  REAL IN;                             ///< VAR_INPUT: the value
  DWORD TM;                            ///< VAR_INPUT: the time since the last call, in ms
  BOOL RESET;                          ///< VAR_INPUT: OUT := 0, OVERFLOW := FALSE
  read_only<REAL, INTEGRAL> OUT;       ///< VAR_OUTPUT: the integral
  read_only<BOOL, INTEGRAL> OVERFLOW;  ///< VAR_OUTPUT: OUT left REAL's range; blocked until RESET

  using VAR_INPUT = pins<&INTEGRAL::IN, &INTEGRAL::TM, &INTEGRAL::RESET>;
  using VAR_OUTPUT = pins<&INTEGRAL::OUT, &INTEGRAL::OVERFLOW>;

 private:
  friend struct iecoop::block_access;

  void body() noexcept {
    if (RESET) {
      OUT = REAL(0.0F);
      OVERFLOW = FALSE;
      return;
    }
    if (OVERFLOW || TM.value() == 0U) return;
    float sum = OUT.get();
    if (detail::integrate(sum, IN, detail::seconds_of(TM.value()))) {
      OUT = sum;
    } else {
      OVERFLOW = TRUE;
    }
  }
};

/// FUNCTION_BLOCK LIN_TRAFO: IN in IN_MIN..IN_MAX mapped linearly onto OUT_MIN..OUT_MAX.
class LIN_TRAFO : public function_block<LIN_TRAFO> {
 public:
  REAL IN;                           ///< VAR_INPUT: the value
  REAL IN_MIN;                       ///< VAR_INPUT: the smallest input value
  REAL IN_MAX;                       ///< VAR_INPUT: the largest input value
  REAL OUT_MIN;                      ///< VAR_INPUT: the output at IN_MIN
  REAL OUT_MAX;                      ///< VAR_INPUT: the output at IN_MAX
  read_only<REAL, LIN_TRAFO> OUT;    ///< VAR_OUTPUT: the value transformed
  read_only<BOOL, LIN_TRAFO> ERROR;  ///< VAR_OUTPUT: IN_MIN = IN_MAX, or IN outside IN_MIN..IN_MAX

  using VAR_INPUT =
      pins<&LIN_TRAFO::IN, &LIN_TRAFO::IN_MIN, &LIN_TRAFO::IN_MAX, &LIN_TRAFO::OUT_MIN, &LIN_TRAFO::OUT_MAX>;
  using VAR_OUTPUT = pins<&LIN_TRAFO::OUT, &LIN_TRAFO::ERROR>;

 private:
  friend struct iecoop::block_access;

  void body() noexcept {
    const float in = IN;
    const float in_min = IN_MIN;
    const float in_max = IN_MAX;
    if (in_min == in_max) {
      ERROR = TRUE;
      return;
    }
    const float low = in_min < in_max ? in_min : in_max;
    const float high = in_min < in_max ? in_max : in_min;
    ERROR = BOOL(!(in >= low && in <= high));
    const float out_min = OUT_MIN;
    const float out_max = OUT_MAX;
    OUT = out_min + (in - in_min) * (out_max - out_min) / (in_max - in_min);
  }
};

namespace detail {

/// STATISTICS_INT (T = INT) and STATISTICS_REAL (T = REAL).
template <class T>
class statistics_of : public function_block<statistics_of<T>> {
  static constexpr bool integral = std::is_same_v<T, INT>;
  static constexpr T largest() noexcept {
    if constexpr (integral) {
      return T(std::numeric_limits<std::int16_t>::max());
    } else {
      return T(std::numeric_limits<float>::max());
    }
  }
  static constexpr T smallest() noexcept {
    if constexpr (integral) {
      return T(std::numeric_limits<std::int16_t>::min());
    } else {
      return T(-std::numeric_limits<float>::max());
    }
  }

 public:
  T IN;                                        ///< VAR_INPUT: the value
  BOOL RESET;                                  ///< VAR_INPUT: starts anew
  read_only<T, statistics_of> MN{largest()};   ///< VAR_OUTPUT: the smallest value (32767, 3.402823466E+38 at first)
  read_only<T, statistics_of> MX{smallest()};  ///< VAR_OUTPUT: the largest value (-32768, -3.402823466E+38 at first)
  read_only<T, statistics_of> AVG;             ///< VAR_OUTPUT: the mean

  using VAR_INPUT = pins<&statistics_of::IN, &statistics_of::RESET>;
  using VAR_OUTPUT = pins<&statistics_of::MN, &statistics_of::MX, &statistics_of::AVG>;

 private:
  friend struct iecoop::block_access;

  void body() noexcept {
    if (RESET) {
      MN = largest();
      MX = smallest();
      AVG = T();
      count_ = 0;
      sum_ = {};
      return;
    }
    if (IN < MN.get()) MN = IN;
    if (IN > MX.get()) MX = IN;
    ++count_;
    if constexpr (integral) {
      sum_ += IN.value();
      AVG = T(static_cast<std::int16_t>(detail::divide_toward_zero(sum_, static_cast<std::int64_t>(count_))));
    } else {
      sum_ += static_cast<double>(IN);
      AVG = T(static_cast<float>(sum_ / static_cast<double>(count_)));
    }
  }

  std::uint64_t count_ = 0;
  std::conditional_t<integral, std::int64_t, double> sum_{};
};

}  // namespace detail

/// FUNCTION_BLOCK STATISTICS_INT: minimum, maximum and mean of an INT over time.
using STATISTICS_INT = detail::statistics_of<INT>;
/// FUNCTION_BLOCK STATISTICS_REAL: minimum, maximum and mean of a REAL over time.
using STATISTICS_REAL = detail::statistics_of<REAL>;

/// FUNCTION_BLOCK VARIANCE: the variance of IN over the calls since the last RESET.
class VARIANCE : public function_block<VARIANCE> {
 public:
  REAL IN;                        ///< VAR_INPUT: the value
  BOOL RESET;                     ///< VAR_INPUT: starts anew
  read_only<REAL, VARIANCE> OUT;  ///< VAR_OUTPUT: the variance

  using VAR_INPUT = pins<&VARIANCE::IN, &VARIANCE::RESET>;
  using VAR_OUTPUT = pins<&VARIANCE::OUT>;

 private:
  friend struct iecoop::block_access;

  // Welford's running mean and sum of squared deviations, in LREAL.
  void body() noexcept {
    if (RESET) {
      OUT = REAL(0.0F);
      count_ = 0;
      mean_ = squares_ = 0.0;
      return;
    }
    const double x = static_cast<float>(IN);
    ++count_;
    const double delta = x - mean_;
    mean_ += delta / static_cast<double>(count_);
    squares_ += delta * (x - mean_);
    OUT = REAL(static_cast<float>(squares_ / static_cast<double>(count_)));
  }

  std::uint64_t count_ = 0;
  double mean_ = 0.0;
  double squares_ = 0.0;
};

}  // namespace iecoop

#include <iecoop/detail/pop_macros.hpp>
