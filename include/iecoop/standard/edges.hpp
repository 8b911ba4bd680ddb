// SPDX-License-Identifier: MIT
// iecoop/standard/edges.hpp — the edge detectors R_TRIG and F_TRIG.
//
//     R_TRIG start_edge;                 // ST: start_edge : R_TRIG;
//     start_edge("CLK"_ = bStart);        // ST: start_edge(CLK := bStart);
//     if (start_edge.Q) ...              // TRUE for the one call after CLK rose
//
// R_TRIG is `Q := CLK AND NOT M; M := CLK;` with M FALSE at the start, so a CLK that is TRUE
// on the first call counts as a rising edge — in every dialect. F_TRIG on a first call with
// CLK FALSE is where the dialects differ: CODESYS and TwinCAT (IEC edition 1) report no edge,
// IEC editions 2 and 3 and MatIEC report one (iecoop/standard/dialect.hpp). Each block is three bytes:
// CLK, Q and the memory.
#pragma once

#include <iecoop/config.hpp>
#include <iecoop/detail/scalar_access.hpp>
#include <iecoop/pou/call_interface.hpp>
#include <iecoop/pou/function_block.hpp>
#include <iecoop/pou/variables.hpp>
#include <iecoop/standard/dialect.hpp>
#include <iecoop/types/elementary.hpp>

#include <iecoop/detail/push_macros.hpp>

namespace iecoop {

/// R_TRIG: Q is TRUE for one call after CLK rose from FALSE to TRUE.
class rising_edge_trigger : public function_block<rising_edge_trigger> {
 public:
  BOOL CLK;                                ///< VAR_INPUT: the signal
  read_only<BOOL, rising_edge_trigger> Q;  ///< VAR_OUTPUT: TRUE on the call where CLK rose

  using VAR_INPUT = pins<&rising_edge_trigger::CLK>;
  using VAR_OUTPUT = pins<&rising_edge_trigger::Q>;

 private:
  friend struct block_access;

  void body() noexcept {
    // Q := CLK AND NOT M; M := CLK; — as a branch on CLK. Computed without one, Clang's code
    // branches on Q, that is on M's load from memory, and a scan of the standard workload
    // took 1.11 x its hand-written twin's time with clang++ 14 instead of 1.03 (measured:
    // docs/performance.md, "Zero overhead on three compilers").
    if (CLK) {
      Q = !M_;
      M_ = TRUE;
    } else {
      Q = FALSE;
      M_ = FALSE;
    }
  }

  BOOL M_;  // CLK at the previous call
};

/// F_TRIG: Q is TRUE for one call after CLK fell from TRUE to FALSE. `D` decides whether a
/// first call with CLK FALSE counts as a falling edge.
template <Dialect D>
class falling_edge_trigger : public function_block<falling_edge_trigger<D>> {
 public:
  BOOL CLK;                                 ///< VAR_INPUT: the signal
  read_only<BOOL, falling_edge_trigger> Q;  ///< VAR_OUTPUT: TRUE on the call where CLK fell

  using VAR_INPUT = pins<&falling_edge_trigger::CLK>;
  using VAR_OUTPUT = pins<&falling_edge_trigger::Q>;

 private:
  friend struct block_access;

  void body() noexcept {
    Q = M_ & !CLK;
    detail::copy_value(M_, CLK);
  }

  // CLK at the previous call. Before the first call it is taken as TRUE where a first call
  // with CLK FALSE fires (IEC ed. 2+: M := NOT CLK with M starting FALSE), FALSE where not.
  BOOL M_{D::f_trig_fires_on_first_call};
};

/// R_TRIG: rising edge detector.
using R_TRIG = rising_edge_trigger;
/// F_TRIG: falling edge detector (the default dialect's: no edge on a first call with CLK FALSE).
using F_TRIG = falling_edge_trigger<default_dialect>;

namespace codesys {
using iecoop::R_TRIG;
using F_TRIG = falling_edge_trigger<dialect>;
}  // namespace codesys
namespace iec {
using iecoop::R_TRIG;
using F_TRIG = falling_edge_trigger<dialect>;
}  // namespace iec
namespace matiec {
using iecoop::R_TRIG;
using F_TRIG = falling_edge_trigger<dialect>;
}  // namespace matiec

}  // namespace iecoop

#include <iecoop/detail/pop_macros.hpp>
