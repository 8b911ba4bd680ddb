// EXPECT: iecoop: this property's Get is for its own block only \(owner_only_get\)
// EXPECT: conversion_owner_only_property\.cpp:20:
// EXPECT-ERRORS: 1
// A property whose Get is PRIVATE is read inside its block with .get() (C++ applies none of the
// property's conversions to a function template's argument), so TO_LREAL(Gain) is
// TO_LREAL(Gain.get()).
#include <iecoop/iecoop.hpp>

using namespace iecoop;

struct FB_Amp : function_block<FB_Amp> {
  REAL Gain_Get() { return 1.5f; }
  // PROPERTY Gain : REAL, its Get PRIVATE
  [[no_unique_address]] property<REAL, &FB_Amp::Gain_Get, nullptr, owner_only_get> Gain{this};
  REAL rIn = 2.0f;
  LREAL lrOut;
  void body() {
#ifdef IECOOP_COMPILE_FAIL
    // lrOut := TO_LREAL(Gain) * rIn;
    lrOut = TO_LREAL(Gain) * rIn;
#else
    // lrOut := TO_LREAL(Gain) * rIn;
    lrOut = TO_LREAL(Gain.get()) * rIn;
#endif
  }
};

int main() {
  FB_Amp fb;
  fb.body();
  return fb.lrOut == 3.0 ? 0 : 1;
}
