// EXPECT: iecoop: the window does not fit in the process image's area
// EXPECT-ERRORS: 1
// EXPECT: io_window_outside_image\.cpp:9:
// A window lies inside its image: the default image has 64 input bytes, %IB60..%IB67 does not fit.
#include <iecoop/io/footprint.hpp>

using namespace iecoop;
#ifdef IECOOP_COMPILE_FAIL
constexpr image_window card = window_of<"%IB60", 8>;
#else
constexpr image_window card = window_of<"%IB60", 4>;
#endif
int main() { return card.bits == 32 ? 0 : 1; }
