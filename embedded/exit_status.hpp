// embedded/exit_status.hpp — how a firmware example ends, and the status the host then sees
// (QEMU's exit status under semihosting, the process's exit status on the host).
#pragma once

#if defined(__arm__)
#include "semihosting.hpp"
#else
#include <cstdlib>
#endif

namespace firmware {

/// The statuses the examples and the start-up code end with.
enum exit_status : int {
  passed = 0,        ///< the example computed what it expected
  failed = 1,        ///< the example computed something else
  iecoop_fault = 2,  ///< iecoop reported a fault (fault_handler.hpp)
  cpu_fault = 3,     ///< a processor exception or abort() (startup.cpp)
};

/// Ends the program with `status`.
[[noreturn]] inline void end(int status) noexcept {
#if defined(__arm__)
  semihosting::exit(status);
#else
  std::exit(status);
#endif
}

}  // namespace firmware
