// EXPECT: iecoop: <A>_TO_<B> takes an A, or a type that widens into A implicitly
// EXPECT: conversion_wrong_source\.cpp:17:
// EXPECT: spelled<'D', ?'I', ?'N', ?'T'>, ?iecoop::detail::spelled<'I', ?'N', ?'T'>
// EXPECT-ERRORS: 1
// INT_TO_REAL of a DINT variable: a DINT is no INT (it does not narrow implicitly); write the
// conversion named after the variable's type, DINT_TO_REAL, or TO_REAL.
#include <iecoop/iecoop.hpp>

using namespace iecoop;

struct FB_Scale : function_block<FB_Scale> {
  var<DINT> diRaw{70000};
  REAL rScaled;
  void body() {
#ifdef IECOOP_COMPILE_FAIL
    // rScaled := INT_TO_REAL(diRaw);
    rScaled = INT_TO_REAL(diRaw);
#else
    // rScaled := DINT_TO_REAL(diRaw);
    rScaled = DINT_TO_REAL(diRaw);
#endif
  }
};

int main() {
  FB_Scale fb;
  fb.body();
  return fb.rScaled == 70000.0f ? 0 : 1;
}
