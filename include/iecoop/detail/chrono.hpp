// SPDX-License-Identifier: MIT
// iecoop/detail/chrono.hpp — std::chrono's durations, clocks and literals, which iecoop uses,
// without the rest of <chrono>. libstdc++'s <chrono> brings C++20's calendars, time zones and
// their text I/O (<sstream>, <istream>, locales) into every translation unit that includes
// it, more than a third of the umbrella header's parse time; its <bits/chrono.h> holds what
// iecoop uses (duration, duration_cast, the clocks, the literals) and is what its own <thread>
// includes. With another standard library (or an older libstdc++): <chrono>.
// IWYU pragma: private, include <chrono>
#pragma once

#include <version>

#if defined(__GLIBCXX__) && __has_include(<bits/chrono.h>)
#include <bits/chrono.h>  // IWYU pragma: export
#else
#include <chrono>  // IWYU pragma: export
#endif
