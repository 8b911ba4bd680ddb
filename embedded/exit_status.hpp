// embedded/exit_status.hpp — how a firmware example ends, and the status the host then sees
// (QEMU's exit status under semihosting, the process's exit status on the host).
#pragma once

#if defined(__arm__)
#include <cstddef>
#include <cstdint>
#include <string_view>

#if defined(IECOOP_FIRMWARE_STACK_REPORT)
#include <iecoop/types/literal_text.hpp>  // the report's number
#endif

#include "semihosting.hpp"

// The stack's bounds, from the linker script (embedded/cortex-m.ld).
extern "C" std::uint32_t __stack_bottom[];
extern "C" std::uint32_t __stack_top[];
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

#if defined(__arm__) && defined(IECOOP_FIRMWARE_STACK_REPORT)
/// What the start-up code writes over the stack before main() (startup.cpp), in a build that
/// reports the stack's high-water mark (the CMake option IECOOP_FIRMWARE_STACK_REPORT, which
/// embedded/size_table.sh turns on for its own build: the report's 300 bytes of code are not
/// counted in the examples' sizes).
inline constexpr std::uint32_t stack_paint = 0xA5C3E187U;

/// The bytes of the stack ever used since reset: from the top down to the deepest word that no
/// longer holds the paint.
inline std::uint32_t stack_high_water() noexcept {
  const std::uint32_t* word = __stack_bottom;
  while (word < __stack_top && *word == stack_paint) ++word;
  return static_cast<std::uint32_t>(reinterpret_cast<std::uintptr_t>(__stack_top) -
                                    reinterpret_cast<std::uintptr_t>(word));
}

/// Writes `stack high-water: <bytes> bytes` to the host's stderr (embedded/size_table.sh reads
/// it; the tests compare stdout only).
inline void report_stack_high_water() noexcept {
  char text[40] = "stack high-water: ";
  char* end = iecoop::detail::write_unsigned(text + 18, stack_high_water());
  for (const char c : std::string_view(" bytes\n")) *end++ = c;
  semihosting::write_stderr(std::string_view(text, static_cast<std::size_t>(end - text)));
}
#endif

/// Ends the program with `status`.
[[noreturn]] inline void end(int status) noexcept {
#if defined(__arm__)
#if defined(IECOOP_FIRMWARE_STACK_REPORT)
  report_stack_high_water();
#endif
  semihosting::exit(status);
#else
  std::exit(status);
#endif
}

}  // namespace firmware
