// EXPECT: iecoop: a conversion \(TO_<type>, <A>_TO_<B>, convert<T>\) takes an elementary value
// EXPECT: conversion_of_block_instance\.cpp:21:
// EXPECT: FB_Valve
// EXPECT-ERRORS: 1
// ST converts no block instance: TO_LREAL(fbValve) does not compile; convert one of its variables
// (here a var<REAL>, which converts as its value).
#include <iecoop/iecoop.hpp>

using namespace iecoop;

struct FB_Valve : function_block<FB_Valve> {
  var<REAL> rPosition{42.5f};
  void body() {}
};

int main() {
  FB_Valve fbValve;
  LREAL lrPosition;
#ifdef IECOOP_COMPILE_FAIL
  // lrPosition := TO_LREAL(fbValve);
  lrPosition = TO_LREAL(fbValve);
#else
  // lrPosition := TO_LREAL(fbValve.rPosition);
  lrPosition = TO_LREAL(fbValve.rPosition);
#endif
  return lrPosition == 42.5 ? 0 : 1;
}
