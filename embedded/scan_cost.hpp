// embedded/scan_cost.hpp — the instructions one scan of an example executes on the target,
// counted under QEMU's -icount (embedded/scan_cost_table.sh; docs/embedded.md, "Cost of a
// scan"). A firmware example calls start() first, begin() and end() around each scan and
// report() at the end. Only a build with IECOOP_FIRMWARE_SCAN_COST (the CMake option of the
// same name) measures; everywhere else the four do nothing.
//
// How: with -icount shift=0 QEMU advances its virtual clock by 1 ns per instruction, and the
// SysTick counts that clock at the core's frequency; the counter is read before and after each
// scan. How many instructions one tick of the counter is, start() measures on a loop of known
// length (two instructions per pass), and the reading's own cost on an empty pair of readings;
// both are taken out. The result is an average over all the scans, in instructions, not cycles:
// QEMU does not model the pipeline (a Cortex-M0+ takes more cycles for a load or a taken branch,
// a Cortex-M7 may issue two instructions in one).
#pragma once

#include <cstdint>

#include "console.hpp"
#include "tick.hpp"

namespace firmware::scan_cost {

#if defined(IECOOP_FIRMWARE_SCAN_COST) && defined(__arm__)

namespace detail {
using tick::detail::syst_csr;  // the SysTick's registers (tick.hpp)
using tick::detail::syst_cvr;
using tick::detail::syst_rvr;
inline std::uint32_t elapsed(std::uint32_t from, std::uint32_t to) { return (from - to) & 0xFFFFFFU; }  // counts down

inline std::uint64_t ticks = 0;              // the scans' ticks
inline std::uint32_t scans = 0;              // how many
inline std::uint32_t at_begin = 0;           // the counter at the last begin()
inline std::uint64_t loop_ticks = 0;         // the calibration loop's
inline std::uint64_t loop_instructions = 0;  // and its instructions
inline std::uint64_t empty_ticks = 0;        // 1000 empty begin()/end() pairs
inline constexpr std::uint32_t empty_pairs = 1000;
}  // namespace detail

inline void begin() noexcept { detail::at_begin = detail::syst_cvr(); }
inline void end() noexcept {
  detail::ticks += detail::elapsed(detail::at_begin, detail::syst_cvr());
  ++detail::scans;
}

/// Starts the SysTick as a free-running counter (no interrupt) and calibrates.
inline void start() noexcept {
  detail::syst_rvr() = 0xFFFFFFU;
  detail::syst_cvr() = 0;
  detail::syst_csr() = 0x5U;  // ENABLE | CLKSOURCE (the core clock), no TICKINT
  constexpr std::uint32_t passes = 200000;
  std::uint32_t n = passes;
  const std::uint32_t before = detail::syst_cvr();
  // Two instructions a pass. GCC hands inline assembly for ARMv6-M over in the divided syntax,
  // where the flag-setting subtraction is written `sub`.
#if defined(__ARM_ARCH_6M__)
  asm volatile("1:\n\tsub %0, #1\n\tbne 1b" : "+l"(n)::"cc");
#else
  asm volatile("1:\n\tsubs %0, #1\n\tbne 1b" : "+l"(n)::"cc");
#endif
  detail::loop_ticks = detail::elapsed(before, detail::syst_cvr());
  detail::loop_instructions = 2ULL * passes;
  std::uint64_t empty = 0;
  for (std::uint32_t i = 0; i < detail::empty_pairs; ++i) {
    begin();
    asm volatile("" ::: "memory");
    const std::uint32_t now = detail::syst_cvr();
    empty += detail::elapsed(detail::at_begin, now);
  }
  detail::empty_ticks = empty;
}

/// Prints `scan cost <name>: <instructions> instructions per scan (<scans> scans)`.
inline void report(const char* name) noexcept {
  using detail::loop_instructions;
  using detail::loop_ticks;
  // Instructions = ticks x loop_instructions / loop_ticks; in tenths, rounded.
  const std::uint64_t net = detail::ticks * detail::empty_pairs - detail::empty_ticks * detail::scans;  // x empty_pairs
  const std::uint64_t tenths = (net * loop_instructions * 10U + loop_ticks * detail::empty_pairs * detail::scans / 2U) /
                               (loop_ticks * detail::empty_pairs * detail::scans);
  print_line("scan cost ", name, ": ", tenths / 10U, ".", tenths % 10U, " instructions per scan (", detail::scans,
             " scans; ", loop_instructions / loop_ticks, " instructions per SysTick tick)");
}

#else

inline void start() noexcept {}
inline void begin() noexcept {}
inline void end() noexcept {}
inline void report(const char*) noexcept {}

#endif

}  // namespace firmware::scan_cost
