// EXPECT: private
// Extending a library block outside the library does not give access to its INTERNAL members.
#include <iecoop/iecoop.hpp>
using namespace iecoop;
namespace lib {
struct tag {};
struct FB_Axis : function_block<FB_Axis>, member_of<tag, FB_Axis> {
  virtual ~FB_Axis() = default;
  virtual void body() {}
  void Calibrate(internal_access<tag>) {}
};
}  // namespace lib
struct FB_App : extends<FB_App, lib::FB_Axis> {
#ifdef IECOOP_COMPILE_FAIL
  void body() override { Calibrate(internal()); }
#else
  void body() override {}
#endif
};
int main() {
  FB_App app;
  app();
}
