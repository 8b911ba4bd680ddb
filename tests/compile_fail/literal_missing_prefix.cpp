// EXPECT: an IEC literal needs a type prefix
// A duration literal needs T# (IEC: 15ms without prefix is an error).
#include <iecoop/iecoop.hpp>

using namespace iecoop;
#ifdef IECOOP_COMPILE_FAIL
constexpr auto t = "15ms"_iec;
#else
constexpr auto t = "T#15ms"_iec;
#endif
static_assert(t.count() == 15);
