// EXPECT: iecoop: `fb.Prop->Member` reaches into a property of interface, POINTER_TO, REFERENCE_TO or STRUCT type
// EXPECT: a value of this type has no members: read the property as a value
// EXPECT-ERRORS: 1
// EXPECT: property_elementary_gone_through\.cpp:17:
// `->` on a property reaches the members of its value; an LREAL has none.
#include <iecoop/iecoop.hpp>
using namespace iecoop;
struct FB_PID : function_block<FB_PID> {
  LREAL fGain = 2.0;
  LREAL Gain_Get() { return fGain; }
  [[no_unique_address]] property<LREAL, &FB_PID::Gain_Get> Gain{this};
  void body() {}
};
int main() {
  FB_PID fbPID;
#ifdef IECOOP_COMPILE_FAIL
  const auto x = fbPID.Gain->value();
#else
  const LREAL x = fbPID.Gain;
#endif
  return x == 2.0 ? 0 : 1;
}
