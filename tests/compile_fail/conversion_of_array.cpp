// EXPECT: iecoop: a conversion \(TO_<type>, <A>_TO_<B>, convert<T>\) takes an elementary value
// EXPECT: conversion_of_array\.cpp:17:
// EXPECT: basic_array
// EXPECT-ERRORS: 1
// ST converts no ARRAY as a whole: INT_TO_REAL(aiValues) does not compile; convert an element
// (an element of a block's var<ARRAY<...>> converts as well).
#include <iecoop/iecoop.hpp>

using namespace iecoop;

struct FB_Average : function_block<FB_Average> {
  var<ARRAY<INT, 1, 3>> aiValues{ARRAY<INT, 1, 3>{3, 4, 5}};
  REAL rFirst;
  void body() {
#ifdef IECOOP_COMPILE_FAIL
    // rFirst := INT_TO_REAL(aiValues);
    rFirst = INT_TO_REAL(aiValues);
#else
    // rFirst := INT_TO_REAL(aiValues[1]);
    rFirst = INT_TO_REAL(aiValues[1]);
#endif
  }
};

int main() {
  FB_Average fb;
  fb.body();
  return fb.rFirst == 3.0f ? 0 : 1;
}
