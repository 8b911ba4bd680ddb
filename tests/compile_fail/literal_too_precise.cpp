// EXPECT: the literal is finer than its type resolves
// TIME resolves whole milliseconds (CODESYS); finer durations need LTIME.
#include <iecoop/iecoop.hpp>

using namespace iecoop;
#ifdef IECOOP_COMPILE_FAIL
constexpr auto t = "T#1.5ms"_iec;
#else
constexpr auto t = "LTIME#1.5ms"_iec;
#endif
static_assert(t.count() > 0);
