// EXPECT: private
// A read_only<T, Owner> variable (how the standard blocks declare their outputs) is read
// from outside but written only by its block.
#include <iecoop/iecoop.hpp>
using namespace iecoop;
struct FB : function_block<FB> {
  read_only<INT, FB> iCount;
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
