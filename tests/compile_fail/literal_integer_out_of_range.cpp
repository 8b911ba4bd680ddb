// EXPECT: the literal's value does not fit its type
// A typed integer literal must fit its type (CDS-TYPEDLIT): INT#40000 is an error.
#include <iecoop/iecoop.hpp>

using namespace iecoop;
#ifdef IECOOP_COMPILE_FAIL
constexpr auto i = "INT#40000"_iec;
#else
constexpr auto i = "DINT#40000"_iec;
#endif
static_assert(i == 40000);
