// A deliberately bad firmware, built only to prove that check_symbols.cmake fails on an image
// that links what iecoop's firmware must not: compiled once per kind of leak, with
// LEAKY_HEAP (malloc), LEAKY_NEW (operator new), LEAKY_THROW (a throw, with -fexceptions) or
// LEAKY_RTTI (typeid, with -frtti); once, LEAKY_DIVISION, to prove that check_divisions.cmake
// fails on an image whose code divides 64-bit integers; and once, LEAKY_DOUBLE, to prove that
// check_no_double.cmake fails on an image that computes in double; and once, LEAKY_TASK_HOOKS,
// to prove that check_task_hooks.cmake fails on an image whose application has a
// freewheeling task and a watchdog. It never runs.
//
// The firmware is linked without a system-call layer and, with the slim package set, without
// libsupc++: so the heap images bring their own _sbrk (as a firmware with a heap would), and
// the throw and RTTI images are linked with their runtime references left unresolved, which
// is enough for the symbol table to show them.
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <typeinfo>

#if defined(LEAKY_TASK_HOOKS)
#include <iecoop/iecoop.hpp>
#endif

namespace {
// volatile: the compiler may not see through it and drop the leak.
volatile int sink = 0;
}  // namespace

#if defined(LEAKY_HEAP) || defined(LEAKY_NEW)
// A heap carved from a static array: what _sbrk does on a firmware that has one.
extern "C" void* _sbrk(std::ptrdiff_t increment) {
  alignas(8) static char arena[1024];
  static std::size_t used = 0;
  void* block = arena + used;
  used += static_cast<std::size_t>(increment);
  return block;
}
#endif

#if defined(LEAKY_NEW)
// A replacement operator new, as a program may define one; it allocates with malloc. Not
// inlined, as it would not be if it came from another file or a library.
[[gnu::noinline]] void* operator new(std::size_t size) { return std::malloc(size); }
void operator delete(void* p) noexcept { std::free(p); }
void operator delete(void* p, std::size_t) noexcept { std::free(p); }
#endif

#if defined(LEAKY_RTTI)
struct shape {
  virtual int corners() const { return 0; }
};
struct square : shape {
  int corners() const override { return 4; }
};
square a_square;
shape* volatile some_shape = &a_square;
#endif

#if defined(LEAKY_DIVISION)
volatile std::uint64_t dividend = 1000000000000ULL;
volatile std::uint64_t divisor = 7;
// What a program's body must not do on a 32-bit core: a 64-bit division by a run-time value.
[[gnu::noinline]] std::uint64_t cycle_body() { return dividend / divisor; }
#endif

#if defined(LEAKY_DOUBLE)
volatile float reading = 1.5F;
// What a REAL-only program must not do on a core without a double FPU: compute in double.
[[gnu::noinline]] int cycle_body() { return static_cast<int>(static_cast<double>(reading) * 3.0); }
#endif

#if defined(LEAKY_TASK_HOOKS)
using namespace iecoop;
struct BACKGROUND_PRG : program<BACKGROUND_PRG> {
  DINT nCount;
  void body() { nCount = nCount + 1; }
};
// TASK Background (freewheeling, PRIORITY := 31, watchdog T#10ms)
application plc{
    task<BACKGROUND_PRG>{"Background", freewheeling{}, 31, watchdog{"T#10ms"_iec}},
    retain_capacity<0>{},
};
#endif

int main() {
#if defined(LEAKY_TASK_HOOKS)
  plc.start();
  plc.run_for("T#5ms"_iec);
  sink = static_cast<int>(BACKGROUND_PRG::instance().nCount > 0);
#elif defined(LEAKY_DOUBLE)
  sink = cycle_body();
#elif defined(LEAKY_DIVISION)
  sink = static_cast<int>(cycle_body());
#elif defined(LEAKY_HEAP)
  void* block = std::malloc(16);
  sink = block != nullptr ? 1 : 0;
  std::free(block);
#elif defined(LEAKY_NEW)
  int* volatile value = new int(42);
  sink = *value;
  delete value;
#elif defined(LEAKY_THROW)
  if (sink == 0) throw sink + 1;
#elif defined(LEAKY_RTTI)
  sink = typeid(*some_shape) == typeid(square) ? 1 : 0;
#endif
  return sink;
}
