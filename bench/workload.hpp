// The standard scan workload, implemented with iecoop (workload_iecoop.cpp) and as plain
// hand-written C++ without the framework (workload_handwritten.cpp; workload_minimal.cpp is
// a leaner variant that does not store the blocks' inputs). All are driven identically:
// scan k runs with the clock at k x 10 ms.
//
// Per scan: CYC := (CYC + 1) MOD 24000; NTON := NCTU := NEDGE := 0; then for each of 1000
// cells K = 0..999, each owning a TON T, a CTU C and an R_TRIG E:
//
//     PH := (CYC + K) MOD 20;
//     T(IN := PH < 15, PT := T#50ms);            IF T.Q THEN NTON := NTON + 1; END_IF;
//     C(CU := (PH MOD 4) < 2, R := ((CYC + K) MOD 500) = 0, PV := 50);
//                                                IF C.Q THEN NCTU := NCTU + 1; END_IF;
//     E(CLK := ((CYC + 3 * K) MOD 6) < 3);       IF E.Q THEN NEDGE := NEDGE + 1; END_IF;
//     ACC := (ACC * 3 + K * 3 - PH) MOD 8191;
//
// Each implementation has one instance of the workload's state (as a PLC program has one),
// and the same three entry points, defined out of line so that the driver cannot fold them.
#pragma once

#include <cstdint>

namespace workload {

/// The variables the cross-check reads after a scan.
struct readings {
  std::int16_t NTON;
  std::int16_t NCTU;
  std::int16_t NEDGE;
  std::int16_t ACC;
};

/// The figures every correct implementation reproduces over `check_scans` scans from the
/// initial state: the sum of NTON + 3*NCTU + 7*NEDGE read after each scan, and the readings
/// after the last scan.
inline constexpr std::uint32_t check_scans = 100000;
inline constexpr std::int64_t check_sum = 346312824;
inline constexpr readings check_last{.NTON = 500, .NCTU = 600, .NEDGE = 0, .ACC = 3722};

/// The scan period: scan k runs at k x scan_period_ms.
inline constexpr std::uint32_t scan_period_ms = 10;

namespace iecoop_side {
/// Puts the workload back into its initial state (every variable 0, every block reset).
void reset() noexcept;
/// Runs scan `k`: sets the cycle clock to k x 10 ms, then runs the program once.
void scan(std::uint32_t k) noexcept;
readings read() noexcept;
}  // namespace iecoop_side

namespace handwritten_side {
void reset() noexcept;
void scan(std::uint32_t k) noexcept;
readings read() noexcept;
}  // namespace handwritten_side

/// The hand-written version without stored inputs (workload_minimal.cpp).
namespace minimal_side {
void reset() noexcept;
void scan(std::uint32_t k) noexcept;
readings read() noexcept;
}  // namespace minimal_side

/// Runs `check_scans` scans of one implementation from its initial state and tells whether
/// it reproduced the figures above (leaving the workload reset again).
template <class Reset, class Scan, class Read>
bool cross_check(Reset reset, Scan scan, Read read) noexcept {
  reset();
  std::int64_t sum = 0;
  readings last{};
  for (std::uint32_t k = 0; k < check_scans; ++k) {
    scan(k);
    last = read();
    sum += last.NTON + 3 * static_cast<std::int64_t>(last.NCTU) + 7 * static_cast<std::int64_t>(last.NEDGE);
  }
  reset();
  return sum == check_sum && last.NTON == check_last.NTON && last.NCTU == check_last.NCTU &&
         last.NEDGE == check_last.NEDGE && last.ACC == check_last.ACC;
}

}  // namespace workload
