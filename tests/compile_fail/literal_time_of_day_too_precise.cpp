// EXPECT: the literal is finer than its type resolves \(DT: 1 s, TOD: 1 ms\)
// A DT counts whole seconds (CODESYS drops a fraction silently; iecoop does not).
#include <iecoop/iecoop.hpp>

using namespace iecoop;
#ifdef IECOOP_COMPILE_FAIL
constexpr DT dt = "DT#2020-02-07-12:55:01.234"_iec;
#else
constexpr LDT dt = "LDT#2020-02-07-12:55:01.234"_iec;
#endif
static_assert(dt.count() > 0);
