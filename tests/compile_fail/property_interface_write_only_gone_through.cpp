// EXPECT: iecoop: `fb.Prop->Member` reaches the member through the value the property's Get gives
// EXPECT: and this property has no Get \(it is write-only\); give the property a Get accessor
// EXPECT-ERRORS: 1
// EXPECT: property_interface_write_only_gone_through\.cpp:39:
// ST's `fbPID.IntegratorBounds.Maximum := 5;` reads IntegratorBounds (its Get) to reach the
// interface behind it: a property without Get cannot be gone through.
#include <iecoop/iecoop.hpp>
using namespace iecoop;
// INTERFACE I_Bounds  PROPERTY Maximum : LREAL
struct I_Bounds : interface_base<I_Bounds> {
  virtual LREAL Maximum_Get() = 0;
  virtual void Maximum_Set(LREAL value) = 0;
  [[no_unique_address]] property<LREAL, &I_Bounds::Maximum_Get, &I_Bounds::Maximum_Set> Maximum{this};
};
struct FB_Bounds : function_block<FB_Bounds, implements<I_Bounds>> {
  LREAL fMaximum;
  void body() {}
  LREAL Maximum_Get() override { return fMaximum; }
  void Maximum_Set(LREAL value) override { fMaximum = value; }
};
// FUNCTION_BLOCK FB_PID   PROPERTY IntegratorBounds : I_Bounds
struct FB_PID : function_block<FB_PID> {
  itf<I_Bounds> _ipBounds;
  void IntegratorBounds_Set(itf<I_Bounds> value) { _ipBounds = value; }
#ifdef IECOOP_COMPILE_FAIL
  [[no_unique_address]] property<itf<I_Bounds>, nullptr, &FB_PID::IntegratorBounds_Set> IntegratorBounds{
      this};  // Set only
#else
  itf<I_Bounds> IntegratorBounds_Get() { return _ipBounds; }
  [[no_unique_address]] property<itf<I_Bounds>, &FB_PID::IntegratorBounds_Get, &FB_PID::IntegratorBounds_Set>
      IntegratorBounds{this};
#endif
  void body() {}
};
int main() {
  FB_Bounds fbBounds;
  FB_PID fbPID;
  fbPID.IntegratorBounds = fbBounds;
  fbPID.IntegratorBounds->Maximum = 5.0;  // fbPID.IntegratorBounds.Maximum := 5;
  return fbBounds.fMaximum == 5.0 ? 0 : 1;
}
