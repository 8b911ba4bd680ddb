// EXPECT: iecoop: an ARRAY compares only with an ARRAY of the same bounds, index by index
// EXPECT: array_compare_other_bounds\.cpp:17:
// EXPECT-ERRORS: 1
// TcUnit's AssertArrayEquals in the kit: ARRAY[1..3] OF INT and ARRAY[0..2] OF INT are not one
// type (ST assigns neither to the other): which element would the first compare with?
#include <iecoop/testing.hpp>
using namespace iecoop;
struct FB_Sort : function_block<FB_Sort> {
  var<ARRAY<INT, 1, 3>> aiValues;
  void body() { aiValues[1] = 1; }
};
TEST_CASE("sorts") {
  FB_Sort fb;
  fb();
#ifdef IECOOP_COMPILE_FAIL
  const ARRAY<INT, 0, 2> aiExpected{1, 0, 0};
  CHECK(fb.aiValues == aiExpected);
#else
  const ARRAY<INT, 1, 3> aiExpected{1, 0, 0};
  CHECK(fb.aiValues == aiExpected);
#endif
}
