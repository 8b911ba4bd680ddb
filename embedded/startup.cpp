// embedded/startup.cpp — what runs before main() on a Cortex-M: the exception vector table,
// the reset handler that prepares RAM and runs the static constructors, and the few runtime
// functions that the C and C++ libraries would otherwise bring, with everything they drag
// along (stdio, signals, a heap).
//
// The firmware is linked with -nostartfiles: newlib's crt0 expects another memory layout and
// a host below it. The layout comes from embedded/cortex-m.ld.
#include <cstdint>

#include "console.hpp"
#include "exit_status.hpp"

// Symbols of the linker script. Declared as arrays: they are addresses, not variables.
extern "C" {
extern std::uint32_t __data_load[];
extern std::uint32_t __data_start[];
extern std::uint32_t __data_end[];
extern std::uint32_t __bss_start[];
extern std::uint32_t __bss_end[];
extern std::uint32_t __stack_bottom[];
extern std::uint32_t __stack_top[];
extern void (*__init_array_start[])();
extern void (*__init_array_end[])();
}

// main() itself may not be called in C++ (and -Wpedantic says so): reach it by its symbol.
extern "C" int firmware_main() __asm__("main");

namespace {

[[noreturn]] void stop_on_cpu_fault(const char* what) noexcept {
#if !defined(__ARM_ARCH_6M__)
  // The report's own code may load a word from an unaligned address, as ARMv7-M and ARMv8-M
  // allow: where a firmware set CCR.UNALIGN_TRP (embedded/traps/unaligned.cpp), clear it, or
  // the report would fault inside the fault handler and lock the core up.
  auto* const ccr = reinterpret_cast<volatile std::uint32_t*>(0xE000ED14U);
  *ccr = *ccr & ~(1U << 3);
#endif
  firmware::print_line("cpu fault: ", what);
  firmware::end(firmware::exit_status::cpu_fault);
}

}  // namespace

extern "C" {

// --- Exception handlers -------------------------------------------------------------------
// Each fault ends the program with a message: under QEMU a test then fails at once instead of
// hanging until its timeout. A firmware that uses an interrupt defines its handler under the
// CMSIS name (SysTick_Handler, ...); the weak definitions here stand in for the others.

[[noreturn]] void iecoop_reset() noexcept;
[[noreturn]] void HardFault_Handler() noexcept { stop_on_cpu_fault("HardFault"); }
[[noreturn]] void iecoop_unexpected_exception() noexcept { stop_on_cpu_fault("unexpected exception"); }
[[noreturn]] void NMI_Handler() noexcept __attribute__((weak, alias("iecoop_unexpected_exception")));
[[noreturn]] void MemManage_Handler() noexcept __attribute__((weak, alias("iecoop_unexpected_exception")));
[[noreturn]] void BusFault_Handler() noexcept __attribute__((weak, alias("iecoop_unexpected_exception")));
[[noreturn]] void UsageFault_Handler() noexcept __attribute__((weak, alias("iecoop_unexpected_exception")));
[[noreturn]] void SVC_Handler() noexcept __attribute__((weak, alias("iecoop_unexpected_exception")));
[[noreturn]] void DebugMon_Handler() noexcept __attribute__((weak, alias("iecoop_unexpected_exception")));
[[noreturn]] void PendSV_Handler() noexcept __attribute__((weak, alias("iecoop_unexpected_exception")));
[[noreturn]] void SysTick_Handler() noexcept __attribute__((weak, alias("iecoop_unexpected_exception")));

// --- Runtime support -----------------------------------------------------------------------

// iecoop calls abort() after a fault handler returned where no fallback exists. newlib's
// abort() raises SIGABRT, which needs signal handling and a _kill the firmware does not have.
[[noreturn]] void abort() noexcept { stop_on_cpu_fault("abort"); }

// A pure virtual function called during construction or destruction. libsupc++'s version
// would go through std::terminate.
[[noreturn]] void __cxa_pure_virtual() noexcept { stop_on_cpu_fault("pure virtual call"); }

// Objects with static storage duration and a destructor register it with __aeabi_atexit,
// naming their module by __dso_handle (normally in crtbegin.o). The firmware never returns
// from main, so there is nothing to register: no exit machinery gets linked.
void* __dso_handle = nullptr;
int __aeabi_atexit(void*, void (*)(void*), void*) noexcept { return 0; }

}  // extern "C"

// --- The vector table ----------------------------------------------------------------------

namespace {

using handler = void (*)();

// The first word is the initial stack pointer, not a handler: a struct keeps both types
// honest, and the table a constant the compiler lays out at build time.
struct vector_table {
  const void* initial_stack_pointer;
  handler system_exceptions[15];
};

}  // namespace

// `used` keeps the compiler from dropping it, KEEP in the linker script the linker.
extern "C" __attribute__((section(".vectors"), used)) const vector_table iecoop_vectors = {
    __stack_top,
    {
        iecoop_reset,        // 1  Reset
        NMI_Handler,         // 2  NMI
        HardFault_Handler,   // 3  HardFault
        MemManage_Handler,   // 4  MemManage
        BusFault_Handler,    // 5  BusFault
        UsageFault_Handler,  // 6  UsageFault
        nullptr,             // 7  reserved
        nullptr,             // 8  reserved
        nullptr,             // 9  reserved
        nullptr,             // 10 reserved
        SVC_Handler,         // 11 SVCall
        DebugMon_Handler,    // 12 DebugMonitor
        nullptr,             // 13 reserved
        PendSV_Handler,      // 14 PendSV
        SysTick_Handler,     // 15 SysTick
    },
};

// --- Reset -------------------------------------------------------------------------------

extern "C" [[noreturn]] void iecoop_reset() noexcept {
#if defined(__ARM_FP)
  // The Cortex-M4F's FPU is off after reset: grant full access to coprocessors 10 and 11
  // (CPACR bits 20..23) before the first floating-point instruction, which would fault.
  auto* const cpacr = reinterpret_cast<volatile std::uint32_t*>(0xE000ED88U);
  *cpacr = *cpacr | (0xFU << 20);
  asm volatile("dsb\n\tisb" ::: "memory");
#endif
#if defined(IECOOP_FIRMWARE_STACK_REPORT)
  // The stack below this function's frame gets a pattern, so that the end of the program can
  // tell how deep the stack ever reached (firmware::stack_high_water, exit_status.hpp).
  std::uint32_t* sp = nullptr;
  asm volatile("mov %0, sp" : "=r"(sp));
  for (std::uint32_t* word = __stack_bottom; word < sp - 16; ++word) *word = firmware::stack_paint;
#endif
  // Initialised variables get their first values from flash; the others start at zero.
  const std::uint32_t* from = __data_load;
  for (std::uint32_t* to = __data_start; to < __data_end; ++to, ++from) *to = *from;
  for (std::uint32_t* to = __bss_start; to < __bss_end; ++to) *to = 0;
  // Constructors of objects with static storage duration, in link order.
  for (auto* constructor = __init_array_start; constructor < __init_array_end; ++constructor) (*constructor)();
  firmware::end(firmware_main());
}
