// EXPECT: internal_access
// METHOD INTERNAL is callable only inside its library: outside, no key can be made.
#include <iecoop/iecoop.hpp>
using namespace iecoop;
namespace lib {
struct tag {};
struct FB : function_block<FB>, member_of<tag, FB> {
  void body() {}
  void Calibrate(internal_access<tag>) {}
};
struct FB_User : function_block<FB_User>, member_of<tag, FB_User> {
  FB fb;
  void body() { fb.Calibrate(internal()); }
};
}  // namespace lib
int main() {
  lib::FB_User user;
#ifdef IECOOP_COMPILE_FAIL
  user.fb.Calibrate(internal_access<lib::tag>{});
#else
  user();
#endif
}
