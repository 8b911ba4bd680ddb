// EXPECT: iecoop: a subrange's lower limit must not exceed its upper limit
// ST's INT(100..0) is no range.
#include <iecoop/iecoop.hpp>
using namespace iecoop;
int main() {
#ifdef IECOOP_COMPILE_FAIL
  subrange<INT, 100, 0> i;
  (void)i;
#else
  subrange<INT, 0, 100> i;
  (void)i;
#endif
}
