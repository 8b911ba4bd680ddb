// EXPECT: iecoop: an ARRAY compares only with an ARRAY of the same element type
// EXPECT: array_compare_other_type\.cpp:13:
// EXPECT-ERRORS: 1
// An ARRAY OF INT and an ARRAY OF DINT are not one type, though INT widens to DINT: ST assigns
// neither ARRAY to the other. Declare the expected values with the result's element type.
#include <iecoop/testing.hpp>
using namespace iecoop;
TEST_CASE("scales") {
  ARRAY<INT, 1, 3> aiResult{10, 20, 30};
  for (INT i = 1; i <= 3; i += 1) aiResult[i] = aiResult[i] * 2;
#ifdef IECOOP_COMPILE_FAIL
  const ARRAY<DINT, 1, 3> adiExpected{20, 40, 60};
  const BOOL xSame = aiResult == adiExpected;
#else
  const ARRAY<INT, 1, 3> aiExpected{20, 40, 60};
  const BOOL xSame = aiResult == aiExpected;
#endif
  CHECK(xSame);
}
