// embedded/semihosting.hpp — the firmware's line to the host: text to the host's stdout and an
// exit status for the host's shell, through ARM semihosting.
//
// A semihosting request is a `bkpt 0xAB` with the operation in r0 and the address of its
// argument block in r1; the debugger, here QEMU started with
// `-semihosting-config enable=on,target=native`, carries it out and leaves its result in r0.
// Without a debugger the breakpoint escalates to a HardFault, so run the firmware under QEMU.
//
// We make the requests ourselves rather than link newlib's rdimon: its printf and stdio
// buffers would bring malloc along, and the firmware must link no heap.
#pragma once

#include <cstddef>
#include <cstdint>
#include <string_view>

namespace firmware::semihosting {

// Operation numbers and the reason code, from Arm's "Semihosting for AArch32 and AArch64".
inline constexpr std::uint32_t op_open = 0x01;
inline constexpr std::uint32_t op_write = 0x05;
inline constexpr std::uint32_t op_exit_extended = 0x20;
inline constexpr std::uint32_t reason_application_exit = 0x20026;  // ADP_Stopped_ApplicationExit

inline std::uint32_t request(std::uint32_t operation, const void* arguments) noexcept {
  // The register variables pin the operands to r0 and r1, where the request expects them.
  register std::uint32_t r0 asm("r0") = operation;
  register const void* r1 asm("r1") = arguments;
  asm volatile("bkpt 0xAB" : "+r"(r0) : "r"(r1) : "memory");
  return r0;
}

inline std::uint32_t address_of(const void* p) noexcept {
  return static_cast<std::uint32_t>(reinterpret_cast<std::uintptr_t>(p));
}

// The host's stdout is the special file ":tt" opened for writing (mode 4, "w"). SYS_WRITE0
// would be shorter, but QEMU sends it to stderr, where a test cannot tell it from QEMU's own
// messages.
// ":tt" opened with mode 4 ("w") is stdout, with mode 8 ("a") stderr.
inline std::uint32_t open_console(std::uint32_t mode) noexcept {
  static constexpr char name[] = ":tt";
  const std::uint32_t block[3] = {address_of(name), mode, sizeof name - 1};
  return request(op_open, block);
}
inline std::uint32_t open_stdout() noexcept { return open_console(4U); }

/// Writes `text` to the host's stdout.
inline void write(std::string_view text) noexcept {
  // Opened on first use, once; -fno-threadsafe-statics keeps libstdc++'s guard functions out.
  static const std::uint32_t handle = open_stdout();
  const std::uint32_t block[3] = {handle, address_of(text.data()), static_cast<std::uint32_t>(text.size())};
  request(op_write, block);
}

/// Writes `text` to the host's stderr: ":tt" opened for appending (mode 8, "a").
inline void write_stderr(std::string_view text) noexcept {
  static const std::uint32_t handle = open_console(8U);
  const std::uint32_t block[3] = {handle, address_of(text.data()), static_cast<std::uint32_t>(text.size())};
  request(op_write, block);
}

/// Ends the program; QEMU exits with `status`. SYS_EXIT proper cannot carry a status on
/// 32-bit ARM (the host sees 0 or 1), its extended form can.
[[noreturn]] inline void exit(int status) noexcept {
  const std::uint32_t block[2] = {reason_application_exit, static_cast<std::uint32_t>(status)};
  request(op_exit_extended, block);
  for (;;) {
    // Only reached without a debugger that ends the program.
  }
}

}  // namespace firmware::semihosting
