// Proves that the cores under QEMU trap an unaligned access, so that the examples passing on the
// Cortex-M0+ (embedded/examples/process_image.cpp and the others) show they make none: it loads
// a word from an odd address and must end in the HardFault handler (status 3), never print the
// word. An ARMv6-M core (the Cortex-M0+, and QEMU's Cortex-M0 that runs its images) always
// traps; an ARMv7-M or ARMv8-M core traps once CCR.UNALIGN_TRP is set, which this image does
// first (an unaligned LDR is otherwise allowed there, and the compiler may use one).
#include <cstdint>

#include "console.hpp"
#include "exit_status.hpp"

namespace {
alignas(4) volatile std::uint8_t bytes[8] = {1, 2, 3, 4, 5, 6, 7, 8};
}  // namespace

int main() {
#if !defined(__ARM_ARCH_6M__)
  // The Configuration and Control Register (ARMv7-M ARM, B3.2.8): bit 3, UNALIGN_TRP.
  auto* const ccr = reinterpret_cast<volatile std::uint32_t*>(0xE000ED14U);
  *ccr = *ccr | (1U << 3);
  asm volatile("dsb\n\tisb" ::: "memory");
#endif
  firmware::print_line("loading a word from an odd address");
  const auto address = reinterpret_cast<std::uintptr_t>(&bytes[1]);
  std::uint32_t value = 0;
  // The load written as the instruction itself: in C++ a misaligned pointer is not allowed at all.
  asm volatile("ldr %0, [%1]" : "=r"(value) : "r"(address) : "memory");
  firmware::print_line("no fault, the word is ", value);
  return firmware::failed;
}
