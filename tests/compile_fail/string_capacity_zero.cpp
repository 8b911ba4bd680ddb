// EXPECT: a STRING needs a capacity of at least 1 character
// STRING(0) holds nothing; the smallest STRING is STRING(1).
#include <iecoop/iecoop.hpp>

using namespace iecoop;
#ifdef IECOOP_COMPILE_FAIL
STRING<0> nothing;
#else
STRING<1> nothing;
#endif
int main() { return nothing.empty() ? 0 : 1; }
