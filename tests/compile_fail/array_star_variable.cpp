// EXPECT: iecoop: ARRAY.*variable length.* exists only as a VAR_IN_OUT
// CODESYS allows ARRAY[*] only in VAR_IN_OUT declarations.
#include <iecoop/iecoop.hpp>
using namespace iecoop;
int main() {
  ARRAY<INT, 1, 3> aData{1, 2, 3};
#ifdef IECOOP_COMPILE_FAIL
  ARRAY<INT, '*'> aView;
  (void)aView;
#else
  in_out<ARRAY<INT, '*'>> aView(aData);
  (void)aView;
#endif
  return aData[1] == 1 ? 0 : 1;
}
