// EXPECT: iecoop: this block does not implement the interface
// Only a block that IMPLEMENTS an interface can be assigned to a variable of it.
#include <iecoop/iecoop.hpp>
using namespace iecoop;
struct I_Named : interface_base<I_Named> {
  virtual STRING<> GetName() = 0;
};
struct FB_Named : function_block<FB_Named, implements<I_Named>> {
  void body() {}
  STRING<> GetName() override { return "named"; }
};
struct FB_Plain : function_block<FB_Plain> {
  void body() {}
  STRING<> GetName() { return "plain"; }  // the same method, but no IMPLEMENTS
};
int main() {
#ifdef IECOOP_COMPILE_FAIL
  FB_Plain fb;
#else
  FB_Named fb;
#endif
  itf<I_Named> ip;
  ip = fb;
  return ip->GetName() == "" ? 1 : 0;
}
