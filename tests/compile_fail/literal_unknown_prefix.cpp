// EXPECT: unknown literal prefix
// The prefix names the literal's type; an unknown one is rejected.
#include <iecoop/iecoop.hpp>

using namespace iecoop;
#ifdef IECOOP_COMPILE_FAIL
constexpr auto x = "TIMER#5s"_iec;
#else
constexpr auto x = "TIME#5s"_iec;
#endif
static_assert(x.count() == 5000);
