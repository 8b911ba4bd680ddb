// EXPECT: iecoop: the bit number of a direct address is 0\.\.7
// A byte has bits 0..7: the bit after %IX0.7 is %IX1.0.
#include <iecoop/io/located.hpp>
using namespace iecoop;
int main() {
#ifdef IECOOP_COMPILE_FAIL
  located<BOOL, "%IX0.8"> bSensor;  // bSensor AT %IX0.8 : BOOL;
#else
  located<BOOL, "%IX1.0"> bSensor;  // bSensor AT %IX1.0 : BOOL;
#endif
  return bSensor ? 1 : 0;
}
