// EXPECT: a RETAIN or PERSISTENT array is written retain<std::array<T, N>>
// ST's `VAR RETAIN aValues : ARRAY[0..2] OF INT; END_VAR` is a retain<std::array<INT, 3>>.
#include <iecoop/iecoop.hpp>
#include <iecoop/runtime/retain.hpp>

#include <array>

using namespace iecoop;

int main() {
#ifdef IECOOP_COMPILE_FAIL
  retain<INT[3]> aValues;
#else
  retain<std::array<INT, 3>> aValues;
#endif
  return aValues->size() == 3 ? 0 : 1;
}
