// EXPECT: Position
// A block that leaves an ABSTRACT method unimplemented is abstract itself; the compiler names
// the method.
#include <iecoop/iecoop.hpp>
using namespace iecoop;
struct FB_Axis : function_block<FB_Axis> {
  virtual ~FB_Axis() = default;
  virtual void body() {}
  virtual LREAL Position() = 0;  // METHOD ABSTRACT Position : LREAL
};
struct FB_Linear : extends<FB_Linear, FB_Axis> {
  void body() override {}
#ifndef IECOOP_COMPILE_FAIL
  LREAL Position() override { return 0.0; }
#endif
};
int main() {
  FB_Linear axis;
  return axis.Position() == 0.0 ? 0 : 1;
}
