// EXPECT: two pins of the block have the same name
// A derived block may not declare a variable its base already has (CODESYS: compile error).
#include <iecoop/iecoop.hpp>
using namespace iecoop;
struct fbA : function_block<fbA> {
  virtual ~fbA() = default;
  INT x;
  using VAR_INPUT = pins<&fbA::x>;
  virtual void body() {}
};
struct fbB : extends<fbB, fbA> {
  void body() override {}
#ifdef IECOOP_COMPILE_FAIL
  INT x;
  using VAR_INPUT = pins<&fbB::x>;
#else
  INT ivar;
  using VAR_INPUT = pins<&fbB::ivar>;
#endif
};
int main() {
  fbB b;
  b();
}
