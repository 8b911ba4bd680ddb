// A consumer's program with a slip that iecoop-check reports (and the C++ compiler accepts):
// the consumer test that builds it with iecoop_check(... BUILD) must fail, naming it.
#include <iecoop/iecoop.hpp>

using namespace iecoop;

// FUNCTION_BLOCK FB_Counter   VAR nCount : INT; END_VAR
struct FB_Counter : function_block<FB_Counter> {
  var<INT> nCount;
  void body() { nCount = nCount + 1; }
};

int main() {
  FB_Counter counter;
  counter();
  counter.nCount = 0;  // CODESYS: the VAR nCount is not writable from outside FB_Counter
  return counter.nCount == 0 ? 0 : 1;
}
