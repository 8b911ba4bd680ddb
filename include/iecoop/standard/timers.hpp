// SPDX-License-Identifier: MIT
// iecoop/standard/timers.hpp — the standard timers TON, TOF, TP and their LTIME forms LTON, LTOF, LTP.
//
//     TON tmr;                                   // ST: tmr : TON;
//     tmr("IN"_ = bStart, "PT"_ = T#5s);          // ST: tmr(IN := bStart, PT := T#5s);
//     if (tmr.Q) ...                             // ST: IF tmr.Q THEN
//
// Each call reads the running cycle's time stamp (cycle_clock): a timer never reads a wall
// clock, and two calls in one cycle see the same time. The behaviour is exactly MatIEC's
// state machines of the IEC 61131-3 timing diagrams (docs/standard-library.md):
//   - the rising edge of IN (TON, TP) or its falling edge (TOF) starts the timer; ET is not
//     updated on that call, so it reads 0 there;
//   - the timer has expired on the first call at which the elapsed time is >= PT; ET then
//     reads exactly PT and stays there (also if PT changes later) until the timer resets;
//   - PT is read on every call: lowered below the elapsed time, the timer expires on the next
//     call; PT = 0 expires on the call after the edge;
//   - TP ignores edges while its pulse runs, and resets ET to 0 once the pulse is over and IN
//     is FALSE (in the same call when IN is already FALSE then).
//
// Outputs are read-only from outside, as in ST. Each timer is as small as its state allows:
// IN, Q, PT, ET, the start time and two bytes of state, 16 bytes for TIME timers.
#pragma once

#include <type_traits>

#include <iecoop/config.hpp>
#include <iecoop/detail/scalar_access.hpp>
#include <iecoop/pou/call_interface.hpp>
#include <iecoop/pou/function_block.hpp>
#include <iecoop/pou/variables.hpp>
#include <iecoop/standard/cycle_clock.hpp>
#include <iecoop/standard/dialect.hpp>
#include <iecoop/types/elementary.hpp>
#include <iecoop/types/time.hpp>

#include <iecoop/detail/push_macros.hpp>

namespace iecoop {

namespace detail {

template <class Time>
concept timer_time = std::is_same_v<Time, TIME> || std::is_same_v<Time, LTIME>;

/// MatIEC's STATE — 0 reset (idle), 1 counting (running), 2 expired — as two flags. (Not a
/// one-byte enum: that is a character type to GCC, which lets it alias every variable, so
/// a loop calling a timer would keep all its variables in memory.)
struct timer_state {
  bool running = false;
  bool expired = false;

  [[nodiscard]] constexpr bool idle() const noexcept { return !running && !expired; }
  constexpr void reset() noexcept { running = expired = false; }
  constexpr void start() noexcept {
    running = true;
    expired = false;
  }
  constexpr void expire() noexcept {
    running = false;
    expired = true;
  }
};

/// One call of a running timer (MatIEC's STATE = 1): sets ET to the time elapsed since
/// `start`, or to PT once that reaches PT — and then tells that the timer has expired.
/// (ET is written here rather than returned with the flag in a struct: GCC 12 packs such a
/// pair into one register and unpacks it again, even inlined.)
template <class Time>
bool run_timer(const Time& start, const Time& pt, Time& et) noexcept {
  const Time elapsed = cycle_clock::now_as<Time>() - start;
  const bool expired = elapsed >= pt;
  // One scalar copy (detail/scalar_access.hpp): ET is a member of the timer. (Two, one in
  // each branch, Clang merges into one store that keeps no type-based alias information.)
  copy_value(et, expired ? pt : elapsed);
  return expired;
}

template <class Time>
constexpr bool check_timer_time() {
  static_assert(timer_time<Time>,
                "iecoop: a timer measures TIME or LTIME; use TON/TOF/TP (TIME) or LTON/LTOF/LTP (LTIME)");
  return true;
}

}  // namespace detail

/**
 * TON, on-delay timer: Q becomes TRUE once IN has been TRUE for PT, and FALSE as soon as IN
 * is FALSE. ET counts the time since IN rose, up to PT. (`Time` is TIME for TON, LTIME for
 * LTON.)
 */
template <class Time>
class on_delay_timer : public function_block<on_delay_timer<Time>> {
  static_assert(detail::check_timer_time<Time>());

 public:
  BOOL IN;                            ///< VAR_INPUT: rising edge starts the timer, FALSE resets it
  read_only<BOOL, on_delay_timer> Q;  ///< VAR_OUTPUT: TRUE while IN has been TRUE for at least PT

 private:
  detail::timer_state state_;

 public:
  Time PT;                             ///< VAR_INPUT: the delay
  read_only<Time, on_delay_timer> ET;  ///< VAR_OUTPUT: the elapsed time, 0 to PT

 private:
  Time start_;

 public:
  using VAR_INPUT = pins<&on_delay_timer::IN, &on_delay_timer::PT>;
  using VAR_OUTPUT = pins<&on_delay_timer::Q, &on_delay_timer::ET>;

 private:
  friend struct block_access;

  void body() noexcept {
    // In state idle the previous IN was FALSE (a call with IN TRUE always leaves idle), so
    // MatIEC's PREV_IN needs no storage here: idle with IN TRUE is the rising edge.
    if (!IN) {
      ET = Time();
      Q = FALSE;
      state_.reset();
    } else if (state_.idle()) {
      state_.start();
      Q = FALSE;
      detail::copy_value(start_, cycle_clock::now_as<Time>());
    } else if (state_.running) {
      if (detail::run_timer(start_, PT, ET.ref())) {
        state_.expire();
        Q = TRUE;
      }
    }
  }
};

/**
 * TOF, off-delay timer: Q is TRUE while IN is TRUE and for PT after IN falls. ET counts the
 * time since IN fell, up to PT. (`Time` is TIME for TOF, LTIME for LTOF.)
 */
template <class Time>
class off_delay_timer : public function_block<off_delay_timer<Time>> {
  static_assert(detail::check_timer_time<Time>());

 public:
  BOOL IN;                             ///< VAR_INPUT: falling edge starts the timer, TRUE resets it
  read_only<BOOL, off_delay_timer> Q;  ///< VAR_OUTPUT: IN, held for PT after IN falls

 private:
  bool running_ = false;
  bool prev_in_ = false;

 public:
  Time PT;                              ///< VAR_INPUT: the delay
  read_only<Time, off_delay_timer> ET;  ///< VAR_OUTPUT: the elapsed time, 0 to PT

 private:
  Time start_;

 public:
  using VAR_INPUT = pins<&off_delay_timer::IN, &off_delay_timer::PT>;
  using VAR_OUTPUT = pins<&off_delay_timer::Q, &off_delay_timer::ET>;

 private:
  friend struct block_access;

  // MatIEC's STATE 2 (expired) behaves as STATE 0 here: with IN FALSE neither does
  // anything (the previous IN is FALSE too), and IN TRUE resets both; so only "running" is
  // kept.
  void body() noexcept {
    if (IN) {
      ET = Time();
      running_ = false;
    } else if (!running_) {
      if (prev_in_) {  // falling edge
        running_ = true;
        detail::copy_value(start_, cycle_clock::now_as<Time>());
      }
    } else if (detail::run_timer(start_, PT, ET.ref())) {
      running_ = false;
    }
    Q = IN || running_;
    prev_in_ = static_cast<bool>(IN);
  }
};

/**
 * TP, pulse timer: a rising edge of IN makes Q TRUE for exactly PT, whatever IN does meanwhile.
 * ET counts the pulse's time up to PT, holds PT while IN stays TRUE after the pulse, and is 0
 * once IN is FALSE. (`Time` is TIME for TP, LTIME for LTP.)
 */
template <class Time>
class pulse_timer : public function_block<pulse_timer<Time>> {
  static_assert(detail::check_timer_time<Time>());

 public:
  BOOL IN;                         ///< VAR_INPUT: rising edge starts a pulse (ignored while one runs)
  read_only<BOOL, pulse_timer> Q;  ///< VAR_OUTPUT: the pulse_timer

 private:
  detail::timer_state state_;

 public:
  Time PT;                          ///< VAR_INPUT: the pulse's length
  read_only<Time, pulse_timer> ET;  ///< VAR_OUTPUT: the pulse_timer's elapsed time, 0 to PT

 private:
  Time start_;

 public:
  using VAR_INPUT = pins<&pulse_timer::IN, &pulse_timer::PT>;
  using VAR_OUTPUT = pins<&pulse_timer::Q, &pulse_timer::ET>;

 private:
  friend struct block_access;

  void body() noexcept {
    // As for TON, idle implies the previous IN was FALSE: idle with IN TRUE is the edge.
    if (state_.idle()) {
      if (IN) {
        state_.start();
        Q = TRUE;
        detail::copy_value(start_, cycle_clock::now_as<Time>());
      }
    } else if (state_.running) {
      if (detail::run_timer(start_, PT, ET.ref())) {
        state_.expire();
        Q = FALSE;
      }
    }
    if (state_.expired && !IN) {
      ET = Time();
      state_.reset();
    }
  }
};

/// TON: on-delay timer (TIME).
using TON = on_delay_timer<TIME>;
/// TOF: off-delay timer (TIME).
using TOF = off_delay_timer<TIME>;
/// TP: pulse timer (TIME).
using TP = pulse_timer<TIME>;
/// LTON: on-delay timer (LTIME).
using LTON = on_delay_timer<LTIME>;
/// LTOF: off-delay timer (LTIME).
using LTOF = off_delay_timer<LTIME>;
/// LTP: pulse timer (LTIME).
using LTP = pulse_timer<LTIME>;

// The timers are the same in every dialect.
namespace codesys {
using iecoop::LTOF;
using iecoop::LTON;
using iecoop::LTP;
using iecoop::TOF;
using iecoop::TON;
using iecoop::TP;
}  // namespace codesys
namespace iec {
using iecoop::LTOF;
using iecoop::LTON;
using iecoop::LTP;
using iecoop::TOF;
using iecoop::TON;
using iecoop::TP;
}  // namespace iec
namespace matiec {
using iecoop::LTOF;
using iecoop::LTON;
using iecoop::LTP;
using iecoop::TOF;
using iecoop::TON;
using iecoop::TP;
}  // namespace matiec

}  // namespace iecoop

#include <iecoop/detail/pop_macros.hpp>
