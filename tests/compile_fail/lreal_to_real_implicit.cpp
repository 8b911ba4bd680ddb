// EXPECT: conversion from
// LREAL to REAL may lose precision, so IEC wants LREAL_TO_REAL.
#include <iecoop/iecoop.hpp>

using namespace iecoop;
int main() {
  const LREAL precise = 0.1;
#ifdef IECOOP_COMPILE_FAIL
  const REAL r = precise;
#else
  const REAL r = LREAL_TO_REAL(precise);
#endif
  return r > 0.0f ? 0 : 1;
}
