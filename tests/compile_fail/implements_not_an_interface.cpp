// EXPECT: iecoop: implements<I\.\.\.> lists interfaces
// implements<> takes interfaces (derived from interface_base), not blocks or other classes.
#include <iecoop/iecoop.hpp>
using namespace iecoop;
struct FB_Base : function_block<FB_Base> {
  virtual ~FB_Base() = default;
  virtual void body() {}
};
struct I_Run : interface_base<I_Run> {
  virtual void Run() = 0;
};
#ifdef IECOOP_COMPILE_FAIL
struct FB_Wrong : function_block<FB_Wrong, implements<FB_Base>> {  // EXTENDS, not IMPLEMENTS
  void body() {}
  void Run() {}
};
#else
struct FB_Wrong : function_block<FB_Wrong, implements<I_Run>> {
  void body() {}
  void Run() override {}
};
#endif
int main() {
  FB_Wrong fb;
  fb.Run();
  return 0;
}
