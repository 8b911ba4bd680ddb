// One feature: a PROPERTY of interface type. ST reaches through it with a dot —
// `fbPID.IntegratorBounds.Maximum := 5;`, `fbPID.IntegratorBounds.Reset();` — and C++ with `->`,
// as through an interface variable: the property's Get gives the interface, then the interface's
// own property Set (or method) runs on the block behind it. The same holds for properties of
// POINTER TO and REFERENCE TO type; of a STRUCT property, `->` reads a field.
#include <fmt/core.h>

#include <iecoop/fmt.hpp>
#include <iecoop/iecoop.hpp>

using namespace iecoop;

// INTERFACE I_Bounds
struct I_Bounds : interface_base<I_Bounds> {
  virtual LREAL Maximum_Get() = 0;  // PROPERTY Maximum : LREAL  (Get, Set)
  virtual void Maximum_Set(LREAL value) = 0;
  [[no_unique_address]] property<LREAL, &I_Bounds::Maximum_Get, &I_Bounds::Maximum_Set> Maximum{this};
  virtual void Reset() = 0;  // METHOD Reset
};

// FUNCTION_BLOCK FB_Bounds IMPLEMENTS I_Bounds
struct FB_Bounds : function_block<FB_Bounds, implements<I_Bounds>> {
  var<LREAL> fMaximum{100.0};  // VAR fMaximum : LREAL := 100.0; END_VAR
  LREAL Maximum_Get() override { return fMaximum; }  // (Get) Maximum := fMaximum;
  void Maximum_Set(LREAL value) override {           // (Set)
    fmt::print("  FB_Bounds.Maximum.Set({})\n", value);
    fMaximum = value;  // fMaximum := Maximum;
  }
  void Reset() override {  // METHOD Reset
    fmt::print("  FB_Bounds.Reset()\n");
    fMaximum = 100.0;  // fMaximum := 100.0;
  }
  void body() {}
};

// TYPE ST_Gains : STRUCT fKp, fTn : LREAL; END_STRUCT END_TYPE
struct ST_Gains {
  LREAL fKp = 1.5;
  LREAL fTn = 2.0;
};

// FUNCTION_BLOCK FB_PID
struct FB_PID : function_block<FB_PID> {
  var<itf<I_Bounds>> _ipBounds;  // VAR _ipBounds : I_Bounds; _stGains : ST_Gains; END_VAR
  var<ST_Gains> _stGains;

  // PROPERTY IntegratorBounds : I_Bounds
  itf<I_Bounds> IntegratorBounds_Get() {  // (Get) IntegratorBounds := _ipBounds;
    fmt::print("  FB_PID.IntegratorBounds.Get\n");
    return _ipBounds;
  }
  void IntegratorBounds_Set(itf<I_Bounds> value) {  // (Set) _ipBounds := IntegratorBounds;
    fmt::print("  FB_PID.IntegratorBounds.Set\n");
    _ipBounds = value;
  }
  [[no_unique_address]] property<itf<I_Bounds>, &FB_PID::IntegratorBounds_Get, &FB_PID::IntegratorBounds_Set>
      IntegratorBounds{this};

  // PROPERTY Gains : ST_Gains  (Get)
  ST_Gains Gains_Get() { return _stGains; }  // (Get) Gains := _stGains;
  [[no_unique_address]] property<ST_Gains, &FB_PID::Gains_Get> Gains{this};

  void body() {}
};

int main() {
  FB_Bounds fbBounds;  // fbBounds : FB_Bounds;
  FB_PID fbPID;        // fbPID : FB_PID;

  fmt::print("fbPID.IntegratorBounds := fbBounds;\n");
  fbPID.IntegratorBounds = fbBounds;  // the outer property's Set
  fmt::print("fbPID.IntegratorBounds.Maximum := 5;\n");
  fbPID.IntegratorBounds->Maximum = 5.0;  // its Get, then I_Bounds' Maximum Set
  fmt::print("fMax := fbPID.IntegratorBounds.Maximum;\n");
  const LREAL fMax = fbPID.IntegratorBounds->Maximum;  // its Get, then I_Bounds' Maximum Get
  fmt::print("  fMax = {}\n", fMax);
  fmt::print("fbPID.IntegratorBounds.Reset();\n");
  fbPID.IntegratorBounds->Reset();  // its Get, then I_Bounds' Reset
  fmt::print("  fbBounds.fMaximum = {}\n", fbBounds.fMaximum);

  // An interface variable takes the property's value, or the block's VAR, as ST assigns them.
  fmt::print("ipBounds := fbPID._ipBounds;  bSame := ipBounds = fbPID.IntegratorBounds;\n");
  itf<I_Bounds> ipBounds = fbPID._ipBounds;
  const BOOL bSame = ipBounds == fbPID.IntegratorBounds;
  fmt::print("  bSame = {}\n", bSame);

  // A STRUCT property's fields are read through `->`; `fbPID.Gains.fKp := 2;` would change a
  // copy and does not compile: assign the whole property (with a Set) instead.
  fmt::print("fbPID.Gains.fKp = {}\n", fbPID.Gains->fKp);  // fbPID.Gains.fKp

  // While the block's interface variable is 0, a call through the property is the fault of a
  // call through an unassigned interface (fault_kind::unassigned_interface): the program stops.
}
