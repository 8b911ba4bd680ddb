// EXPECT: conversion from
// A BOOL is TRUE or FALSE, not a number (BOOL b := 1; is an error in ST).
#include <iecoop/iecoop.hpp>

using namespace iecoop;
int main() {
#ifdef IECOOP_COMPILE_FAIL
  const BOOL b = 1;
#else
  const BOOL b = TRUE;
#endif
  return b ? 0 : 1;
}
