// EXPECT: iecoop: ARRAYs compare element by element, and these elements have no =
// EXPECT: array_compare_elements_without_equal\.cpp:23:
// EXPECT-ERRORS: 1
// ST compares no STRUCTs with =, and neither does C++ unless the STRUCT says how: an ARRAY of
// them compares once the STRUCT has its ==, here C++'s member by member.
#include <iecoop/iecoop.hpp>
using namespace iecoop;
#ifdef IECOOP_COMPILE_FAIL
struct ST_Point {
  INT x;
  INT y;
};
#else
struct ST_Point {
  INT x;
  INT y;
  bool operator==(const ST_Point&) const = default;
};
#endif
int main() {
  ARRAY<ST_Point, 1, 2> aPoints{ST_Point{1, 2}};
  const ARRAY<ST_Point, 1, 2> aExpected{ST_Point{1, 2}};
  const BOOL xDiffer = aPoints != aExpected;
  return xDiffer ? 1 : 0;
}
