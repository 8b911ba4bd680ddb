// EXPECT: iecoop: a window holds at least one bit, byte or word
// EXPECT-ERRORS: 1
// EXPECT: io_window_empty\.cpp:9:
// A window of no values is no window: give its count.
#include <iecoop/io/footprint.hpp>

using namespace iecoop;
#ifdef IECOOP_COMPILE_FAIL
constexpr image_window card = window_of<"%IB0", 0>;
#else
constexpr image_window card = window_of<"%IB0", 1>;
#endif
int main() { return card.bits == 8 ? 0 : 1; }
