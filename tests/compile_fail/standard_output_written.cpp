// EXPECT: private|protected|inaccessible
// The outputs of a standard block (Q, ET, CV, ...) are read-only from outside, as in ST:
// assigning one does not compile; reading it does.
#include <iecoop/iecoop.hpp>
using namespace iecoop;
int main() {
  TON tmr;
  tmr("IN"_ = TRUE, "PT"_ = TIME(10));
#ifdef IECOOP_COMPILE_FAIL
  tmr.Q = TRUE;  // tmr.Q := TRUE;  (not allowed in ST either)
#else
  BOOL q = tmr.Q;     // q := tmr.Q;
  tmr.PT = TIME(20);  // inputs may be assigned
  if (q) return 1;
#endif
  return 0;
}
