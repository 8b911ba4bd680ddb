// EXPECT: only explicitly
// EXPECT: spelled<'D', 'I', 'N', 'T'>
// EXPECT: spelled<'I', 'N', 'T'>
// EXPECT-ERRORS: 1
// Assigning a DINT to an INT input is a narrowing, which ST converts only explicitly: the
// error names both types and so the conversion to write, DINT_TO_INT.
#include <iecoop/iecoop.hpp>
using namespace iecoop;
struct FB : function_block<FB> {
  INT iAmount;
  using VAR_INPUT = pins<&FB::iAmount>;
  void body() {}
};
int main() {
  FB fb;
  const DINT dintVar = 5;
#ifdef IECOOP_COMPILE_FAIL
  fb.iAmount = dintVar;  // fb.iAmount := dintVar;
#else
  fb.iAmount = DINT_TO_INT(dintVar);
#endif
  fb();
  return fb.iAmount == 5 ? 0 : 1;
}
