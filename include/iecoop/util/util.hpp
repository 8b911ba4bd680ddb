// SPDX-License-Identifier: MIT
// iecoop/util/util.hpp — the CODESYS Util library's blocks, the layer above the standard ones
// (docs/util.md): controllers (PD, PID, PID_FIXCYCLE), mathematical blocks (DERIVATIVE,
// INTEGRAL, LIN_TRAFO, STATISTICS_INT, STATISTICS_REAL, VARIANCE), signals (BLINK, GEN,
// FREQ_MEASURE), function manipulators (CHARCURVE, RAMP_INT, RAMP_REAL), analog monitors
// (HYSTERESIS, LIMITALARM), BCD conversions (BCD_TO_INT, INT_TO_BCD) and bit functions
// (EXTRACT, PACK, PUTBIT, UNPACK). No heap, no exceptions: usable on a microcontroller.
#pragma once

// IWYU pragma: begin_exports
#include <iecoop/util/analog_monitors.hpp>
#include <iecoop/util/bcd_conversions.hpp>
#include <iecoop/util/bit_byte_functions.hpp>
#include <iecoop/util/controllers.hpp>
#include <iecoop/util/function_manipulators.hpp>
#include <iecoop/util/mathematical_functions.hpp>
#include <iecoop/util/signals.hpp>
// IWYU pragma: end_exports
