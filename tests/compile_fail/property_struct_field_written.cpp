// EXPECT: operand types are .+const iecoop::LREAL|no viable overloaded '='|read-only object|returns a const value
// EXPECT-ERRORS: 1
// EXPECT: property_struct_field_written\.cpp:26:
// `fb.Limits.fHigh := 5;` for a PROPERTY Limits of STRUCT type would change the copy that Get
// returned, not the block (CODESYS refuses it): the fields read through `->` are const, and the
// compiler says so in its own words (no iecoop message can reach a field's assignment). The fix
// is to assign the whole property.
#include <iecoop/iecoop.hpp>
using namespace iecoop;
// TYPE ST_Limits : STRUCT fLow, fHigh : LREAL; END_STRUCT END_TYPE
struct ST_Limits {
  LREAL fLow = 0.0;
  LREAL fHigh = 10.0;
};
// FUNCTION_BLOCK FB_PID   PROPERTY Limits : ST_Limits
struct FB_PID : function_block<FB_PID> {
  ST_Limits _stLimits;
  ST_Limits Limits_Get() { return _stLimits; }
  void Limits_Set(ST_Limits value) { _stLimits = value; }
  [[no_unique_address]] property<ST_Limits, &FB_PID::Limits_Get, &FB_PID::Limits_Set> Limits{this};
  void body() {}
};
int main() {
  FB_PID fbPID;
#ifdef IECOOP_COMPILE_FAIL
  fbPID.Limits->fHigh = 5.0;  // fbPID.Limits.fHigh := 5;
#else
  ST_Limits stLimits = fbPID.Limits;  // stLimits := fbPID.Limits;
  stLimits.fHigh = 5.0;               // stLimits.fHigh := 5;
  fbPID.Limits = stLimits;            // fbPID.Limits := stLimits;
#endif
  return fbPID.Limits->fHigh == 5.0 ? 0 : 1;  // reading a field is allowed
}
