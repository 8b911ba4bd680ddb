// EXPECT: iecoop: hierarchical addresses \(%IW2\.5\.7\.1\) depend on a fieldbus configuration
// Only flat addresses are supported: hierarchical ones (and %I*) need a device
// configuration iecoop does not have.
#include <iecoop/io/located.hpp>
using namespace iecoop;
int main() {
#ifdef IECOOP_COMPILE_FAIL
  located<WORD, "%IW2.5.7.1"> wValue;  // wValue AT %IW2.5.7.1 : WORD;
#else
  located<WORD, "%IW2"> wValue;  // wValue AT %IW2 : WORD;
#endif
  return wValue == 0 ? 0 : 1;
}
