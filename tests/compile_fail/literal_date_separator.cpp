// EXPECT: a date literal separates its fields with '-'
// IEC writes a DT's date and time of day joined by '-', never by a space or 'T'.
#include <iecoop/iecoop.hpp>

using namespace iecoop;
#ifdef IECOOP_COMPILE_FAIL
constexpr DT dt = "DT#2026-11-23T12:30:00"_iec;
#else
constexpr DT dt = "DT#2026-11-23-12:30:00"_iec;
#endif
static_assert(dt.count() > 0);
