// embedded/tick.hpp — the time base of the scheduler example: a count of ticks, each one
// millisecond of machine time.
//
// On the target the count comes from the Cortex-M SysTick timer, whose interrupt handler
// does nothing but increment it; the main loop sleeps (WFI) until the count moves and then
// runs the application for the ticks it has not run yet. The interrupt never touches the
// application, so nothing is shared with it but one word. Built for the host, the same example
// has no interrupt: waiting for the next tick simply counts it.
#pragma once

#include <cstdint>

namespace firmware::tick {

#if defined(__arm__)

namespace detail {
// The one word the SysTick interrupt writes; a 32-bit load or store is atomic on Cortex-M.
inline volatile std::uint32_t count = 0;

// SysTick registers (Armv7-M Architecture Reference Manual, B3.3).
inline volatile std::uint32_t& syst_csr() { return *reinterpret_cast<volatile std::uint32_t*>(0xE000E010U); }
inline volatile std::uint32_t& syst_rvr() { return *reinterpret_cast<volatile std::uint32_t*>(0xE000E014U); }
inline volatile std::uint32_t& syst_cvr() { return *reinterpret_cast<volatile std::uint32_t*>(0xE000E018U); }
}  // namespace detail

/// Starts the SysTick: an interrupt every `core_clocks_per_tick` cycles of the core clock.
/// On hardware that is the core clock divided by 1000 for a 1 ms tick.
inline void start(std::uint32_t core_clocks_per_tick) noexcept {
  detail::syst_rvr() = core_clocks_per_tick - 1U;  // counts from the reload value down to 0
  detail::syst_cvr() = 0;                          // any write clears the counter
  detail::syst_csr() = 0x7U;                       // ENABLE | TICKINT | CLKSOURCE (the core clock)
}

/// What SysTick_Handler does: the firmware defines the handler (its name is in the vector
/// table of startup.cpp) and calls this.
inline void on_interrupt() noexcept { detail::count = detail::count + 1U; }

/// The ticks since start().
[[nodiscard]] inline std::uint32_t count() noexcept { return detail::count; }

/// Sleeps until the next interrupt (the SysTick's, in this firmware).
inline void wait() noexcept { asm volatile("wfi" ::: "memory"); }

#else

namespace detail {
inline std::uint32_t count = 0;
}  // namespace detail

inline void start(std::uint32_t) noexcept {}
[[nodiscard]] inline std::uint32_t count() noexcept { return detail::count; }
/// On the host a tick passes whenever the example waits for one.
inline void wait() noexcept { ++detail::count; }

#endif

}  // namespace firmware::tick
