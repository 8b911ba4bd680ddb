// EXPECT: incomplete|undefined template
// implements<I...> is the last template argument of function_block<> or extends<>, not a base
// class of its own.
#include <iecoop/iecoop.hpp>
using namespace iecoop;
struct I_Run : interface_base<I_Run> {
  virtual void Run() = 0;
};
#ifdef IECOOP_COMPILE_FAIL
struct FB_Runner : function_block<FB_Runner>, implements<I_Run> {
#else
struct FB_Runner : function_block<FB_Runner, implements<I_Run>> {
#endif
  void body() {}
  void Run() override {}
};
int main() {
  FB_Runner fb;
  fb.Run();
  return 0;
}
