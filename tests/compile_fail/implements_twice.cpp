// EXPECT: iecoop: the block extended already implements this interface
// A block that EXTENDS a block inherits its interfaces; listing one of them again in
// implements<> is rejected (C++ would hold the interface twice).
#include <iecoop/iecoop.hpp>
using namespace iecoop;
struct I_Run : interface_base<I_Run> {
  virtual void Run() = 0;
};
struct I_Stop : interface_base<I_Stop> {
  virtual void Stop() = 0;
};
struct FB_Base : function_block<FB_Base, implements<I_Run>> {
  virtual void body() {}
  void Run() override {}
};
#ifdef IECOOP_COMPILE_FAIL
struct FB_Derived : extends<FB_Derived, FB_Base, implements<I_Run, I_Stop>> {
#else
struct FB_Derived : extends<FB_Derived, FB_Base, implements<I_Stop>> {
#endif
  void Run() override {}
  void Stop() override {}
};
int main() {
  FB_Derived fb;
  itf<I_Run> run = fb;
  run->Run();
  return 0;
}
