// EXPECT: private
// A read_only<T, Owner> variable cannot be overwritten from outside by copying another
// block's variable into it.
#include <iecoop/iecoop.hpp>
using namespace iecoop;
struct FB : function_block<FB> {
  read_only<INT, FB> iCount;
  void body() { iCount = iCount + 1; }
};
int main() {
  FB a;
  FB b;
  a();
#ifdef IECOOP_COMPILE_FAIL
  b.iCount = a.iCount;
#endif
  const INT read = b.iCount;
  return read == 0 ? 0 : 1;
}
