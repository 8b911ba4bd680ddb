// EXPECT: the literal's value does not fit its type
// EXPECT-ERRORS: 1
// A lower unit overflows, and the duration is beyond TIME besides: no TIME literal spells it, so
// the error is the range (it used to propose the duration wrapped to 32 bits, T#704ms).
#include <iecoop/iecoop.hpp>

using namespace iecoop;
int main() {
#ifdef IECOOP_COMPILE_FAIL
  constexpr TIME t = "T#49d17h2m47s1000ms"_iec;
#else
  constexpr LTIME t = "LTIME#49d17h2m48s"_iec;
#endif
  return t.count() > 0 ? 0 : 1;
}
