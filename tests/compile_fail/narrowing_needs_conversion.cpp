// EXPECT: conversion from
// IEC: no implicit conversion from a larger to a smaller type (DINT to INT).
#include <iecoop/iecoop.hpp>

using namespace iecoop;
int main() {
  const DINT wide = 5;
#ifdef IECOOP_COMPILE_FAIL
  const INT narrow = wide;
#else
  const INT narrow = DINT_TO_INT(wide);
#endif
  return narrow == 5 ? 0 : 1;
}
