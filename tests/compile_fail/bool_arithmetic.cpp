// EXPECT: BOOL is not a number
// EXPECT-ERRORS: 1
// ST has no arithmetic on BOOL: `n := b + 1;` does not compile. C++ would compute with the
// BOOL as 0 or 1 through its conversion to bool; iecoop rejects it, and only once.
#include <iecoop/iecoop.hpp>
using namespace iecoop;
int main() {
  const BOOL b = TRUE;
#ifdef IECOOP_COMPILE_FAIL
  const INT n = b + 1;
#else
  const INT n = BOOL_TO_INT(b) + 1;
#endif
  return n == 2 ? 0 : 1;
}
