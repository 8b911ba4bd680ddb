// EXPECT: no VAR_INPUT or VAR_IN_OUT of the name spelled in
// EXPECT-ERRORS: 1
// EXPECT: spelled<'I', 'M'>
// A named argument must name an input of the block (here a typo: 'IM' for 'IN').
#include <iecoop/iecoop.hpp>
using namespace iecoop;
struct FB : function_block<FB> {
  BOOL IN;
  using VAR_INPUT = pins<&FB::IN>;
  void body() {}
};
int main() {
  FB fb;
#ifdef IECOOP_COMPILE_FAIL
  fb("IM"_ = TRUE);
#else
  fb("IN"_ = TRUE);
#endif
}
