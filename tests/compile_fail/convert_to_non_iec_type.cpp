// EXPECT: convert<To>: To must be an IEC elementary type
// The IEC conversions produce IEC types; a C++ int is obtained with .value().
#include <iecoop/iecoop.hpp>

using namespace iecoop;
int main() {
#ifdef IECOOP_COMPILE_FAIL
  const auto n = convert<int>(REAL(2.5f));
#else
  const auto n = convert<DINT>(REAL(2.5f)).value();
#endif
  return n == 3 ? 0 : 1;
}
