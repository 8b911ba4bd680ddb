// SPDX-License-Identifier: MIT
// iecoop/util/analog_monitors.hpp — the CODESYS Util library's analog monitors HYSTERESIS and
// LIMITALARM.
//
//     fbHyst(IN := iTemp, HIGH := 220, LOW := 200);   fbHyst("IN"_ = iTemp, "HIGH"_ = 220, "LOW"_ = 200);
//     bHeater := fbHyst.OUT;                          bHeater = fbHyst.OUT;
//     fbAlarm(IN := iLevel, HIGH := 900, LOW := 100); fbAlarm("IN"_ = iLevel, "HIGH"_ = 900, "LOW"_ = 100);
//
// HYSTERESIS: OUT becomes TRUE when IN < LOW and FALSE when IN > HIGH; between the two (LOW <=
// IN <= HIGH) it keeps its value — TRUE on the low side, a heating thermostat. It starts FALSE.
// With LOW > HIGH (left open by the documentation) a value below LOW switches OUT on first: the
// test IN < LOW comes first.
//
// LIMITALARM: O = IN > HIGH, U = IN < LOW, IL = neither. With LOW > HIGH (left open) a value
// above HIGH and below LOW at once is reported as O alone: O and U are never both TRUE.
#pragma once

#include <iecoop/config.hpp>
#include <iecoop/pou/call_interface.hpp>
#include <iecoop/pou/function_block.hpp>
#include <iecoop/pou/variables.hpp>
#include <iecoop/types/elementary.hpp>

#include <iecoop/detail/push_macros.hpp>

namespace iecoop {

/// FUNCTION_BLOCK HYSTERESIS: OUT TRUE below LOW, FALSE above HIGH, held in between.
class HYSTERESIS : public function_block<HYSTERESIS> {
 public:
  INT IN;                           ///< VAR_INPUT: the value
  INT HIGH;                         ///< VAR_INPUT: the upper limit
  INT LOW;                          ///< VAR_INPUT: the lower limit
  read_only<BOOL, HYSTERESIS> OUT;  ///< VAR_OUTPUT: TRUE once IN < LOW, FALSE once IN > HIGH

  using VAR_INPUT = pins<&HYSTERESIS::IN, &HYSTERESIS::HIGH, &HYSTERESIS::LOW>;
  using VAR_OUTPUT = pins<&HYSTERESIS::OUT>;

 private:
  friend struct block_access;

  void body() noexcept {
    if (IN.value() < LOW.value()) {
      OUT = TRUE;
    } else if (IN.value() > HIGH.value()) {
      OUT = FALSE;
    }
  }
};

/// FUNCTION_BLOCK LIMITALARM: O above HIGH, U below LOW, IL in between.
class LIMITALARM : public function_block<LIMITALARM> {
 public:
  INT IN;                          ///< VAR_INPUT: the value
  INT HIGH;                        ///< VAR_INPUT: the upper limit
  INT LOW;                         ///< VAR_INPUT: the lower limit
  read_only<BOOL, LIMITALARM> O;   ///< VAR_OUTPUT: IN > HIGH
  read_only<BOOL, LIMITALARM> U;   ///< VAR_OUTPUT: IN < LOW (and not above HIGH)
  read_only<BOOL, LIMITALARM> IL;  ///< VAR_OUTPUT: neither O nor U

  using VAR_INPUT = pins<&LIMITALARM::IN, &LIMITALARM::HIGH, &LIMITALARM::LOW>;
  using VAR_OUTPUT = pins<&LIMITALARM::O, &LIMITALARM::U, &LIMITALARM::IL>;

 private:
  friend struct block_access;

  void body() noexcept {
    const bool over = IN.value() > HIGH.value();
    const bool under = !over && IN.value() < LOW.value();
    O = BOOL(over);
    U = BOOL(under);
    IL = BOOL(!over && !under);
  }
};

}  // namespace iecoop

#include <iecoop/detail/pop_macros.hpp>
