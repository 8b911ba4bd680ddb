// EXPECT: private
// A block's VAR can be read from outside, as CODESYS allows, but not written.
#include <iecoop/iecoop.hpp>
using namespace iecoop;
struct FB : function_block<FB> {
  var<INT> iCount;
  void body() { iCount = iCount + 1; }
};
int main() {
  FB fb;
  fb();
#ifdef IECOOP_COMPILE_FAIL
  fb.iCount = 5;
#endif
  const INT read = fb.iCount;
  return read == 1 ? 0 : 1;
}
