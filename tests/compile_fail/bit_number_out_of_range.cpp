// EXPECT: iecoop: bit<N>\(x\): N counts from 0 \(the least significant bit\) to the width less one
// ST's wStatus.16 does not compile for a WORD: its bits are 0..15.
#include <iecoop/iecoop.hpp>
using namespace iecoop;
int main() {
  WORD wStatus = 0;
#ifdef IECOOP_COMPILE_FAIL
  bit<16>(wStatus) = TRUE;
#else
  bit<15>(wStatus) = TRUE;
#endif
  return wStatus == 0x8000 ? 0 : 1;
}
