// Helpers for the tests of the standard function blocks.
#pragma once

#include <cstdint>

#include <iecoop/standard/cycle_clock.hpp>
#include <iecoop/types/time.hpp>

namespace iecoop_test {

/// Sets the cycle clock to `time_ms` milliseconds.
inline void at_ms(std::uint64_t time_ms) { iecoop::cycle_clock::set(iecoop::LTIME::from_ticks(time_ms * 1'000'000)); }

/// `n` milliseconds as TIME.
inline iecoop::TIME ms(std::uint32_t n) { return iecoop::TIME::from_ticks(n); }

}  // namespace iecoop_test
