// SPDX-License-Identifier: MIT
// iecoop/standard/bistables.hpp — the bistables SR (set dominant) and RS (reset dominant).
//
//     SR latch;                                 // ST: latch : SR;
//     latch("S1"_ = bStart, "R"_ = bStop);       // ST: latch(S1 := bStart, R := bStop);
//
// SR is `Q1 := S1 OR (NOT R AND Q1)`, RS is `Q1 := NOT R1 AND (S OR Q1)`: with both inputs
// TRUE, SR's Q1 is TRUE and RS's FALSE. The same in every dialect; three bytes each.
#pragma once

#include <iecoop/config.hpp>
#include <iecoop/pou/call_interface.hpp>
#include <iecoop/pou/function_block.hpp>
#include <iecoop/pou/variables.hpp>
#include <iecoop/types/elementary.hpp>

#include <iecoop/detail/push_macros.hpp>

namespace iecoop {

/// SR: set-dominant bistable.
class set_dominant_latch : public function_block<set_dominant_latch> {
 public:
  BOOL S1;                                 ///< VAR_INPUT: set (dominant)
  BOOL R;                                  ///< VAR_INPUT: reset
  read_only<BOOL, set_dominant_latch> Q1;  ///< VAR_OUTPUT: the stored bit

  using VAR_INPUT = pins<&set_dominant_latch::S1, &set_dominant_latch::R>;
  using VAR_OUTPUT = pins<&set_dominant_latch::Q1>;

 private:
  friend struct block_access;

  void body() noexcept { Q1 = S1 | ((!R) & Q1.get()); }
};

/// RS: reset-dominant bistable.
class reset_dominant_latch : public function_block<reset_dominant_latch> {
 public:
  BOOL S;                                    ///< VAR_INPUT: set
  BOOL R1;                                   ///< VAR_INPUT: reset (dominant)
  read_only<BOOL, reset_dominant_latch> Q1;  ///< VAR_OUTPUT: the stored bit

  using VAR_INPUT = pins<&reset_dominant_latch::S, &reset_dominant_latch::R1>;
  using VAR_OUTPUT = pins<&reset_dominant_latch::Q1>;

 private:
  friend struct block_access;

  void body() noexcept { Q1 = (!R1) & (S | Q1.get()); }
};

/// SR: set-dominant bistable.
using SR = set_dominant_latch;
/// RS: reset-dominant bistable.
using RS = reset_dominant_latch;

namespace codesys {
using iecoop::RS;
using iecoop::SR;
}  // namespace codesys
namespace iec {
using iecoop::RS;
using iecoop::SR;
}  // namespace iec
namespace matiec {
using iecoop::RS;
using iecoop::SR;
}  // namespace matiec

}  // namespace iecoop

#include <iecoop/detail/pop_macros.hpp>
