// EXPECT: iecoop: a conversion \(TO_<type>, <A>_TO_<B>, convert<T>\) takes an elementary value
// EXPECT: conversion_of_struct\.cpp:20:
// EXPECT: ST_Pos
// EXPECT-ERRORS: 1
// ST converts no STRUCT as a whole: convert<LREAL>(stPos) (TO_LREAL(stPos)) does not compile;
// convert a member.
#include <iecoop/iecoop.hpp>

using namespace iecoop;

struct ST_Pos {
  REAL x;
  REAL y;
};

int main() {
  const ST_Pos stPos{.x = 1.5f, .y = 2.0f};
  LREAL lrX;
#ifdef IECOOP_COMPILE_FAIL
  lrX = convert<LREAL>(stPos);
#else
  lrX = convert<LREAL>(stPos.x);
#endif
  return lrX == 1.5 ? 0 : 1;
}
