// One feature: an INTERFACE. Two blocks implement it; an interface variable refers to either
// and calls the implementation of the block it was assigned; Implements<> is the same
// interface as a C++ constraint, for generic code without dispatch.
#include <fmt/core.h>

#include <iecoop/fmt.hpp>
#include <iecoop/iecoop.hpp>

using namespace iecoop;

// INTERFACE I_Drive
struct I_Drive : interface_base<I_Drive> {
  struct Start_vars {
    INT iSpeed;  // METHOD Start : BOOL  VAR_INPUT iSpeed : INT; END_VAR
  };
  virtual BOOL Start(args<Start_vars> in) = 0;
  virtual STRING<> Name_Get() = 0;  // PROPERTY Name : STRING  (Get)
  [[no_unique_address]] property<STRING<>, &I_Drive::Name_Get> Name{this};
};

// FUNCTION_BLOCK FB_DirectOnLine IMPLEMENTS I_Drive
struct FB_DirectOnLine : function_block<FB_DirectOnLine, implements<I_Drive>> {
  BOOL Start(args<Start_vars> in) override {
    BOOL Start = in.iSpeed == 100;  // Start := iSpeed = 100;   one speed only
    return Start;
  }
  STRING<> Name_Get() override { return "direct on line"; }
  void body() {}
};

// FUNCTION_BLOCK FB_Inverter IMPLEMENTS I_Drive
struct FB_Inverter : function_block<FB_Inverter, implements<I_Drive>> {
  var<INT> iReference;  // VAR iReference : INT; END_VAR
  BOOL Start(args<Start_vars> in) override {
    iReference = in.iSpeed;                          // iReference := iSpeed;
    BOOL Start = in.iSpeed > 0 && in.iSpeed <= 120;  // Start := iSpeed > 0 AND iSpeed <= 120;
    return Start;
  }
  STRING<> Name_Get() override { return "inverter"; }
  void body() {}
};

// Generic code: any block implementing I_Drive, called on its own type (no virtual call).
template <class Drive>
  requires Implements<Drive, I_Drive>
BOOL start_at_full_speed(Drive& drive) {
  return drive.Start(100);
}

int main() {
  FB_DirectOnLine fbDol;  // fbDol : FB_DirectOnLine;
  FB_Inverter fbVfd;      // fbVfd : FB_Inverter;
  itf<I_Drive> ipDrive;   // ipDrive : I_Drive;

  fmt::print("unassigned: ipDrive <> 0 is {}\n", ipDrive != 0);  // a call now would be a fault
  for (int i = 0; i < 2; ++i) {
    if (i == 0) {
      ipDrive = fbDol;  // ipDrive := fbDol;
    } else {
      ipDrive = fbVfd;  // ipDrive := fbVfd;
    }
    BOOL bAt60 = ipDrive->Start({"iSpeed"_ = 60});  // bAt60 := ipDrive.Start(iSpeed := 60);
    BOOL bAt100 = ipDrive->Start(100);             // bAt100 := ipDrive.Start(100);
    fmt::print("{:<15} Start(60) {:<5}  Start(100) {}\n", ipDrive->Name.get(), bAt60, bAt100);
  }
  fmt::print("inverter reference {}\n", fbVfd.iReference);
  fmt::print("generic:  {} {}\n", start_at_full_speed(fbDol), start_at_full_speed(fbVfd));
}
