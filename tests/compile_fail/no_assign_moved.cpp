// EXPECT: iecoop: the block, or a block it EXTENDS, is declared no_assign
// EXPECT: no_assign_moved\.cpp:27:
// EXPECT-ERRORS: 1
// A block that EXTENDS a no_assign block is not assigned either — the assignment would copy
// the base block's variables — and a move assignment is an assignment.
#include <iecoop/iecoop.hpp>
#include <utility>
using namespace iecoop;
// {attribute 'no_assign'}
// FUNCTION_BLOCK FB_Channel
struct FB_Channel : function_block<FB_Channel, attributes<no_assign>> {
  POINTER_TO<BYTE> pBuffer;
  virtual ~FB_Channel() = default;
  virtual void body() {}
};
// FUNCTION_BLOCK FB_Serial EXTENDS FB_Channel
struct FB_Serial : extends<FB_Serial, FB_Channel> {
  UDINT udiBaud = 9600;
  void body() override {}
};
FB_Serial make() { return FB_Serial{}; }
int main() {
  FB_Serial fbA;
  fbA.udiBaud = 19200;
  FB_Serial fbB;
#ifdef IECOOP_COMPILE_FAIL
  fbB = std::move(fbA);
#else
  fbB.udiBaud = fbA.udiBaud;
#endif
  FB_Serial fbC = make();  // constructing one from another is no assignment
  return fbB.udiBaud == 19200 && fbC.udiBaud == 9600 ? 0 : 1;
}
