// SPDX-License-Identifier: MIT
// iecoop/util/signals.hpp — the CODESYS Util library's signal blocks: BLINK (a pulse train),
// GEN (a periodic function generator, with GEN_MODE) and FREQ_MEASURE (the frequency of a BOOL).
//
//     fbBlink(ENABLE := TRUE, TIMELOW := T#500ms, TIMEHIGH := T#200ms);
//                              fbBlink("ENABLE"_ = TRUE, "TIMELOW"_ = "T#500ms"_iec, "TIMEHIGH"_ = "T#200ms"_iec);
//     fbGen(MODE := GEN_MODE.SINE, BASE := TRUE, PERIOD := T#2s, AMPLITUDE := 100);
//                              fbGen("MODE"_ = GEN_MODE::SINE, "BASE"_ = TRUE, "PERIOD"_ = "T#2s"_iec,
//                                    "AMPLITUDE"_ = INT(100));
//     fbFreq(IN := xPulse, PERIODS := 4);   fbFreq("IN"_ = xPulse, "PERIODS"_ = INT(4));
//
// Each reads the running cycle's time stamp (cycle_clock), as the standard timers do: BLINK and
// GEN in TIME's milliseconds, FREQ_MEASURE in LTIME's nanoseconds (a frequency from whole
// milliseconds would be coarse at short cycles). docs/util.md has every choice made where the
// documentation leaves the behaviour open.
#pragma once

#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>

#include <iecoop/config.hpp>
#include <iecoop/detail/constant_division.hpp>
#include <iecoop/pou/call_interface.hpp>
#include <iecoop/pou/function_block.hpp>
#include <iecoop/pou/variables.hpp>
#include <iecoop/standard/cycle_clock.hpp>
#include <iecoop/types/elementary.hpp>
#include <iecoop/types/enumeration.hpp>
#include <iecoop/types/time.hpp>

#include <iecoop/detail/push_macros.hpp>

namespace iecoop {

/**
 * FUNCTION_BLOCK BLINK: while ENABLE is TRUE, OUT is FALSE for TIMELOW, then TRUE for TIMEHIGH,
 * and again. Enabling starts with the FALSE phase; each phase lasts its time from the cycle that
 * began it, and ends on the first call at which that time has passed (so a phase is a whole
 * number of cycles, at least its time). While ENABLE is FALSE, OUT keeps its value (write
 * `fbBlink.OUT AND bEnable` for FALSE), as documented.
 */
class BLINK : public function_block<BLINK> {
 public:
  BOOL ENABLE;                 ///< VAR_INPUT: TRUE: blinking
  TIME TIMELOW;                ///< VAR_INPUT: how long OUT is FALSE
  TIME TIMEHIGH;               ///< VAR_INPUT: how long OUT is TRUE
  read_only<BOOL, BLINK> OUT;  ///< VAR_OUTPUT: the blinking signal

  using VAR_INPUT = pins<&BLINK::ENABLE, &BLINK::TIMELOW, &BLINK::TIMEHIGH>;
  using VAR_OUTPUT = pins<&BLINK::OUT>;

 private:
  friend struct block_access;

  void body() noexcept {
    const TIME now = cycle_clock::now_as<TIME>();
    if (!ENABLE) {
      enabled_ = false;
      return;
    }
    if (!enabled_) {
      enabled_ = true;
      OUT = FALSE;
      start_ = now;
      return;
    }
    const TIME phase = OUT ? TIMEHIGH : TIMELOW;
    if (now - start_ >= phase) {
      OUT = !OUT;
      start_ = now;
    }
  }

  TIME start_;  // when the running phase began
  bool enabled_ = false;
};

/// TYPE GEN_MODE : (TRIANGLE, TRIANGLE_POS, SAWTOOTH_RISE, SAWTOOTH_FALL, RECTANGLE, SINUS,
/// COSINUS, SINE, COSINE); END_TYPE — GEN's waveforms (SINUS and COSINUS are SINE and COSINE).
enum class GEN_MODE : INT::rep {
  TRIANGLE,       ///< -AMPLITUDE .. +AMPLITUDE and back
  TRIANGLE_POS,   ///< 0 .. +AMPLITUDE and back
  SAWTOOTH_RISE,  ///< -AMPLITUDE rising to +AMPLITUDE
  SAWTOOTH_FALL,  ///< +AMPLITUDE falling to -AMPLITUDE
  RECTANGLE,      ///< -AMPLITUDE for the first half, +AMPLITUDE for the second
  SINUS,          ///< AMPLITUDE x sin
  COSINUS,        ///< AMPLITUDE x cos
  SINE,           ///< AMPLITUDE x sin
  COSINE,         ///< AMPLITUDE x cos
};
template <>
inline constexpr auto enum_components<GEN_MODE> =
    components<GEN_MODE::TRIANGLE, GEN_MODE::TRIANGLE_POS, GEN_MODE::SAWTOOTH_RISE, GEN_MODE::SAWTOOTH_FALL,
               GEN_MODE::RECTANGLE, GEN_MODE::SINUS, GEN_MODE::COSINUS, GEN_MODE::SINE, GEN_MODE::COSINE>{};

/**
 * FUNCTION_BLOCK GEN: a periodic function of amplitude AMPLITUDE. The period is PERIOD of the
 * cycle clock's time (BASE TRUE) or CYCLES calls (BASE FALSE). With x the position in the
 * period, 0 <= x < 1 — the time since the period began over PERIOD, or the calls since over
 * CYCLES; the first call after the start or a RESET is x = 0 —, OUT is, for A = AMPLITUDE:
 *   TRIANGLE       -A + 4Ax (x < 1/2), 3A - 4Ax           SAWTOOTH_RISE  -A + 2Ax
 *   TRIANGLE_POS   2Ax (x < 1/2), 2A - 2Ax                SAWTOOTH_FALL   A - 2Ax
 *   RECTANGLE      -A (x < 1/2), +A                       SINE, SINUS     A sin(2 pi x)
 *                                                         COSINE, COSINUS A cos(2 pi x)
 * The straight waveforms in integer arithmetic (truncating toward zero, e.g. -A + 4 A t / T), the
 * sine and cosine rounded to the nearest INT. RESET TRUE sets OUT to 0 and restarts the period;
 * a PERIOD of T#0s or CYCLES <= 0 gives 0.
 */
class GEN : public function_block<GEN> {
 public:
  GEN_MODE MODE = GEN_MODE::TRIANGLE;  ///< VAR_INPUT: the waveform
  BOOL BASE;                           ///< VAR_INPUT: TRUE: the period is PERIOD; FALSE: CYCLES calls
  TIME PERIOD = TIME(1000);            ///< VAR_INPUT: the period in time (BASE TRUE)
  INT CYCLES = 1000;                   ///< VAR_INPUT: the period in calls (BASE FALSE)
  INT AMPLITUDE;                       ///< VAR_INPUT: the amplitude
  BOOL RESET;                          ///< VAR_INPUT: OUT := 0, the period restarts
  read_only<INT, GEN> OUT;             ///< VAR_OUTPUT: the function's value

  using VAR_INPUT = pins<&GEN::MODE, &GEN::BASE, &GEN::PERIOD, &GEN::CYCLES, &GEN::AMPLITUDE, &GEN::RESET>;
  using VAR_OUTPUT = pins<&GEN::OUT>;

 private:
  friend struct block_access;

  void body() noexcept {
    const TIME now = cycle_clock::now_as<TIME>();
    if (RESET) {
      OUT = INT(0);
      started_ = false;
      return;
    }
    if (!started_) {
      started_ = true;
      start_ = now;
      calls_ = 0;
    }
    std::int64_t position = 0;
    std::int64_t length = 0;
    if (BASE) {
      const std::uint32_t period = PERIOD.count();
      length = period;
      if (period > 0) {
        // The period's start moves on by whole periods as they pass, so that the time since it
        // stays short of TIME's wrap at 49.7 days (where a difference modulo 2^32 would jump).
        std::uint32_t elapsed = now.count() - start_.count();
        if (elapsed >= period) {
          start_ = TIME::from_ticks(start_.count() + elapsed / period * period);
          elapsed %= period;
        }
        position = elapsed;
      }
    } else {
      length = CYCLES.value();
      if (length > 0) {
        calls_ %= static_cast<std::uint32_t>(length);
        position = calls_;
      }
      ++calls_;
    }
    OUT = INT(static_cast<std::int16_t>(length > 0 ? value_at(position, length) : 0));
  }

  [[nodiscard]] std::int64_t value_at(std::int64_t t, std::int64_t period) const noexcept {
    const std::int64_t a = AMPLITUDE.value();
    const bool first_half = 2 * t < period;
    switch (MODE) {
      case GEN_MODE::TRIANGLE: return first_half ? -a + share(4 * a, t, period) : 3 * a - share(4 * a, t, period);
      case GEN_MODE::TRIANGLE_POS: return first_half ? share(2 * a, t, period) : 2 * a - share(2 * a, t, period);
      case GEN_MODE::SAWTOOTH_RISE: return -a + share(2 * a, t, period);
      case GEN_MODE::SAWTOOTH_FALL: return a - share(2 * a, t, period);
      case GEN_MODE::RECTANGLE: return first_half ? -a : a;
      case GEN_MODE::SINUS:
      case GEN_MODE::SINE: return std::llround(static_cast<double>(a) * std::sin(angle(t, period)));
      case GEN_MODE::COSINUS:
      case GEN_MODE::COSINE: return std::llround(static_cast<double>(a) * std::cos(angle(t, period)));
    }
    return 0;
  }
  // k t / period, truncated toward zero (no libgcc 64-bit division on a 32-bit core).
  static std::int64_t share(std::int64_t k, std::int64_t t, std::int64_t period) noexcept {
    return detail::divide_toward_zero(k * t, period);
  }
  static double angle(std::int64_t t, std::int64_t period) noexcept {
    constexpr double two_pi = 6.283185307179586476925286766559;
    return two_pi * static_cast<double>(t) / static_cast<double>(period);
  }

  TIME start_;               // when the running period began (BASE TRUE)
  std::uint32_t calls_ = 0;  // calls since the period began (BASE FALSE)
  bool started_ = false;
};

/**
 * FUNCTION_BLOCK FREQ_MEASURE: the frequency of IN in Hz, the average over the last PERIODS
 * (1..10) periods, a period being the time from one rising edge of IN to the next (on the
 * cycle clock: the block must be called more often than IN changes). The first rising edge
 * after the start, a RESET or a change of PERIODS only starts the measurement; VALID is FALSE
 * until PERIODS periods have been measured. VALID is FALSE again while the time since the last
 * rising edge is longer than three times the average period ("the time between two rising
 * edges > 3 * OUT", read as three periods), and from an edge that ends such a period to the
 * next edge; OUT keeps the last average meanwhile (the long period counts in the next one).
 * PERIODS outside 1..10: OUT 0, VALID FALSE. RESET: OUT 0, VALID FALSE, the periods forgotten.
 */
class FREQ_MEASURE : public function_block<FREQ_MEASURE> {
 public:
  BOOL IN;                              ///< VAR_INPUT: the signal
  INT PERIODS = 1;                      ///< VAR_INPUT: how many periods to average, 1..10
  BOOL RESET;                           ///< VAR_INPUT: restarts the measurement
  read_only<REAL, FREQ_MEASURE> OUT;    ///< VAR_OUTPUT: the frequency in Hz
  read_only<BOOL, FREQ_MEASURE> VALID;  ///< VAR_OUTPUT: OUT is a measurement

  using VAR_INPUT = pins<&FREQ_MEASURE::IN, &FREQ_MEASURE::PERIODS, &FREQ_MEASURE::RESET>;
  using VAR_OUTPUT = pins<&FREQ_MEASURE::OUT, &FREQ_MEASURE::VALID>;

 private:
  friend struct block_access;
  static constexpr int most = 10;

  void body() noexcept {
    const LTIME now = cycle_clock::now();
    const bool rising = IN && !previous_in_;
    previous_in_ = static_cast<bool>(IN);
    const int periods = PERIODS.value();
    if (RESET || periods < 1 || periods > most || periods != periods_) {
      restart(periods);
      if (RESET || periods < 1 || periods > most) return;
    }
    if (rising) {
      if (edges_ > 0) {
        const std::uint64_t period = (now - last_edge_).count();
        jumped_ = average_ > 0 && period > 3 * average_;  // against the average before it
        durations_[static_cast<std::size_t>(next_)] = period;
        next_ = (next_ + 1) % most;
        if (measured_ < most) ++measured_;
      }
      if (edges_ < 2) ++edges_;
      last_edge_ = now;
      if (measured_ >= periods) {
        std::uint64_t total = 0;
        for (int i = 1; i <= periods; ++i) total += durations_[static_cast<std::size_t>((next_ + most - i) % most)];
        if (total > 0) {  // (two edges in one cycle's calls are no period)
          average_ = detail::divide_u64(total, static_cast<std::uint64_t>(periods));
          OUT = REAL(static_cast<float>(static_cast<double>(periods) * 1e9 / static_cast<double>(total)));
        }
      }
    }
    const bool measured = measured_ >= periods && average_ > 0;
    const bool late = measured && (now - last_edge_).count() > 3 * average_;
    VALID = BOOL(measured && !late && !jumped_);
  }

  void restart(int periods) noexcept {
    OUT = REAL(0.0F);
    VALID = FALSE;
    edges_ = 0;
    measured_ = 0;
    next_ = 0;
    average_ = 0;
    jumped_ = false;
    periods_ = periods;
  }

  std::array<std::uint64_t, most> durations_{};  // the last periods, in ns (a ring)
  LTIME last_edge_;
  std::uint64_t average_ = 0;  // of the last PERIODS periods, in ns
  int periods_ = 1;
  int next_ = 0;         // where the next period goes
  int measured_ = 0;     // periods measured, up to 10
  int edges_ = 0;        // rising edges seen, up to 2
  bool jumped_ = false;  // the last period was longer than 3 x the average before it
  bool previous_in_ = false;
};

}  // namespace iecoop

#include <iecoop/detail/pop_macros.hpp>
