// SPDX-License-Identifier: MIT
// iecoop/util/function_manipulators.hpp — the CODESYS Util library's function manipulators:
// CHARCURVE (a characteristic curve of up to 11 POINTs), RAMP_INT and RAMP_REAL (a slope limiter).
//
//     KL : ARRAY[0..10] OF POINT := [(X:=0,Y:=0), (X:=250,Y:=50), ...];
//     fbCurve(IN := iCounter, N := 5, P := KL);       fbCurve("IN"_ = iCounter, "N"_ = BYTE(5), "P"_ = KL);
//     fbRamp(IN := rSet, ASCEND := 25.0, DESCEND := 20.0, TIMEBASE := T#1s);
//                                                     fbRamp("IN"_ = rSet, "ASCEND"_ = REAL(25.0), "DESCEND"_ =
//                                                     REAL(20.0),
//                                                            "TIMEBASE"_ = "T#1s"_iec);
//
// CHARCURVE interpolates linearly between the two points around IN, in 64-bit integer arithmetic
// (Y0 + (IN - X0) * (Y1 - Y0) / (X1 - X0), the division truncating toward zero as ST's does).
// ERR 0: no error; 1: the points are not in ascending X (checked from P[0] up to the segment
// of IN, so completely only when IN is the largest X, as documented); 2: IN is outside
// P[0].X .. P[N-1].X, and OUT is the nearer end point's Y; 4: N is not 2..11, and OUT keeps
// its value (as it does with ERR 1). Two points of the same X are a step: IN at that X reads
// the first one's Y.
//
// RAMP_INT and RAMP_REAL move OUT toward IN by at most ASCEND up and DESCEND down (DESCEND is
// a magnitude) per TIMEBASE of the cycle clock's time, or per call where TIMEBASE is T#0s. OUT
// starts at 0. With a TIMEBASE, the first call (and the first after a RESET) only takes the
// time: the slope needs an interval. RESET stops the ramp, OUT keeps its value, and the ramp
// goes on from there once RESET is FALSE again (as documented for RAMP_REAL). RAMP_INT keeps
// the fraction of an increment a call did not use, so that over any stretch in one direction
// OUT moves exactly as far as ASCEND x time / TIMEBASE allows (rounded down). A negative
// ASCEND or DESCEND (left open) lets OUT not move in that direction.
#pragma once

#include <cstdint>
#include <type_traits>

#include <iecoop/config.hpp>
#include <iecoop/detail/constant_division.hpp>
#include <iecoop/pou/call_interface.hpp>
#include <iecoop/pou/function_block.hpp>
#include <iecoop/pou/variables.hpp>
#include <iecoop/standard/cycle_clock.hpp>
#include <iecoop/types/array.hpp>
#include <iecoop/types/elementary.hpp>
#include <iecoop/types/time.hpp>

#include <iecoop/detail/push_macros.hpp>

namespace iecoop {

/// TYPE POINT : STRUCT X : INT; Y : INT; END_STRUCT — a point of a CHARCURVE.
struct POINT {
  INT X;
  INT Y;
};

/// FUNCTION_BLOCK CHARCURVE: IN mapped onto the curve of the N points P[0..N-1].
class CHARCURVE : public function_block<CHARCURVE> {
 public:
  INT IN;                          ///< VAR_INPUT: the input signal
  BYTE N;                          ///< VAR_INPUT: the number of points, 2..11
  in_out<ARRAY<POINT, 0, 10>> P;   ///< VAR_IN_OUT: the points, in ascending X
  read_only<INT, CHARCURVE> OUT;   ///< VAR_OUTPUT: the value on the curve
  read_only<BYTE, CHARCURVE> ERR;  ///< VAR_OUTPUT: 0, 1 (order), 2 (IN outside), 4 (N)

  using VAR_INPUT = pins<&CHARCURVE::IN, &CHARCURVE::N>;
  using VAR_IN_OUT = pins<&CHARCURVE::P>;
  using VAR_OUTPUT = pins<&CHARCURVE::OUT, &CHARCURVE::ERR>;

 private:
  friend struct iecoop::block_access;

  void body() noexcept {
    const unsigned n = N.value();
    if (n < 2U || n > 11U) {
      ERR = BYTE(4);
      return;
    }
    const ARRAY<POINT, 0, 10>& p = P.get();
    const std::int32_t in = IN.value();
    const auto x = [&p](unsigned i) { return static_cast<std::int32_t>(p[static_cast<int>(i)].X.value()); };
    const auto y = [&p](unsigned i) { return static_cast<std::int32_t>(p[static_cast<int>(i)].Y.value()); };
    if (in < x(0)) {
      OUT = INT(static_cast<std::int16_t>(y(0)));
      ERR = BYTE(2);
      return;
    }
    for (unsigned i = 1; i < n; ++i) {
      if (x(i) < x(i - 1)) {
        ERR = BYTE(1);
        return;
      }
      if (in <= x(i)) {
        // In 64 bits: (IN - X0) * (Y1 - Y0) reaches 65535 * 65535, beyond a DINT.
        const std::int64_t dx = x(i) - x(i - 1);
        const std::int64_t product = static_cast<std::int64_t>(in - x(i - 1)) * (y(i) - y(i - 1));
        const std::int64_t value = dx == 0 ? y(i - 1) : y(i - 1) + detail::divide_toward_zero(product, dx);
        OUT = INT(static_cast<std::int16_t>(value));
        ERR = BYTE(0);
        return;
      }
    }
    OUT = INT(static_cast<std::int16_t>(y(n - 1)));
    ERR = BYTE(2);
  }
};

namespace detail {

/// RAMP_INT (T = INT) and RAMP_REAL (T = REAL).
template <class T>
class slope_limiter : public function_block<slope_limiter<T>> {
 public:
  T IN;                             ///< VAR_INPUT: the input value
  T ASCEND;                         ///< VAR_INPUT: the largest rise per TIMEBASE
  T DESCEND;                        ///< VAR_INPUT: the largest fall per TIMEBASE (a magnitude)
  TIME TIMEBASE;                    ///< VAR_INPUT: the time of ASCEND and DESCEND; T#0s: per call
  BOOL RESET;                       ///< VAR_INPUT: stops the ramp (OUT keeps its value)
  read_only<T, slope_limiter> OUT;  ///< VAR_OUTPUT: IN, with its slope limited

  using VAR_INPUT = pins<&slope_limiter::IN, &slope_limiter::ASCEND, &slope_limiter::DESCEND, &slope_limiter::TIMEBASE,
                         &slope_limiter::RESET>;
  using VAR_OUTPUT = pins<&slope_limiter::OUT>;

 private:
  friend struct iecoop::block_access;
  static constexpr bool integral = std::is_same_v<T, INT>;

  void body() noexcept {
    const TIME now = cycle_clock::now_as<TIME>();
    const bool first = !timed_;
    const std::uint32_t elapsed = first ? 0U : static_cast<std::uint32_t>(now.count() - last_.count());
    last_ = now;
    timed_ = true;
    if (RESET) {
      timed_ = false;
      if constexpr (integral) carry_.rest = 0;
      return;
    }
    const std::uint32_t base = static_cast<std::uint32_t>(TIMEBASE.count());
    if constexpr (integral) {
      step_int(base, elapsed);
    } else {
      step_real(base, elapsed);
    }
  }

  void step_int(std::uint32_t base, std::uint32_t elapsed) noexcept {
    const std::int32_t out = OUT.get().value();
    const std::int32_t diff = static_cast<std::int32_t>(IN.value()) - out;
    if (diff == 0) {
      carry_.rest = 0;
      return;
    }
    const int direction = diff > 0 ? 1 : -1;
    const std::int32_t rate_value = direction > 0 ? ASCEND.value() : DESCEND.value();
    const std::int64_t rate = rate_value < 0 ? 0 : rate_value;
    const std::int64_t distance = diff > 0 ? diff : -static_cast<std::int64_t>(diff);
    std::int64_t steps = 0;
    if (base == 0U) {
      steps = rate;
    } else {
      if (direction != carry_.direction) carry_.rest = 0;  // a new stretch: the fraction was for the other way
      carry_.rest += rate * elapsed;
      steps = static_cast<std::int64_t>(detail::divide_u64(static_cast<std::uint64_t>(carry_.rest), base));
      carry_.rest -= steps * base;
    }
    carry_.direction = direction;
    if (steps >= distance) {
      steps = distance;
      carry_.rest = 0;
    }
    OUT = INT(static_cast<std::int16_t>(out + direction * static_cast<std::int32_t>(steps)));
  }

  void step_real(std::uint32_t base, std::uint32_t elapsed) noexcept {
    const float out = OUT.get();
    const float in = IN;
    float up = ASCEND;
    float down = DESCEND;
    if (base != 0U) {
      up = up * static_cast<float>(elapsed) / static_cast<float>(base);
      down = down * static_cast<float>(elapsed) / static_cast<float>(base);
    }
    if (up < 0.0F) up = 0.0F;
    if (down < 0.0F) down = 0.0F;
    if (in > out) {
      OUT = in - out <= up ? in : out + up;
    } else if (in < out) {
      OUT = out - in <= down ? in : out - down;
    }
  }

  // RAMP_INT's fraction of an increment: increments x milliseconds not yet spent, in the
  // direction of the stretch under way (RAMP_REAL has none: no bytes).
  struct carry {
    std::int64_t rest = 0;
    int direction = 0;
  };
  struct no_carry {};

  TIME last_;
  bool timed_ = false;  // last_ holds the time of the previous call
  [[no_unique_address]] std::conditional_t<integral, carry, no_carry> carry_;
};

}  // namespace detail

/// FUNCTION_BLOCK RAMP_INT: IN with its slope limited to ASCEND / DESCEND per TIMEBASE (INT).
using RAMP_INT = detail::slope_limiter<INT>;
/// FUNCTION_BLOCK RAMP_REAL: IN with its slope limited to ASCEND / DESCEND per TIMEBASE (REAL).
using RAMP_REAL = detail::slope_limiter<REAL>;

}  // namespace iecoop

#include <iecoop/detail/pop_macros.hpp>
