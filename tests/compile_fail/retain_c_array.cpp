// EXPECT: a RETAIN or PERSISTENT array is written retain<ARRAY<T, 1, N>>
// ST's `VAR RETAIN aValues : ARRAY[0..2] OF INT; END_VAR` is a retain<ARRAY<INT, 0, 2>>.
#include <iecoop/iecoop.hpp>
#include <iecoop/runtime/retain.hpp>

using namespace iecoop;

int main() {
#ifdef IECOOP_COMPILE_FAIL
  retain<INT[3]> aValues;
#else
  retain<ARRAY<INT, 0, 2>> aValues;
  aValues[2] = 5;
#endif
  return UPPER_BOUND(aValues, 1) == 2 ? 0 : 1;
}
