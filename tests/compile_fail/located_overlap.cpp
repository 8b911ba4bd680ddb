// EXPECT: iecoop: two located variables overlap
// Two located variables listed in LOCATED must not share a bit: %IB0 holds %IX0.5.
// (Eight BOOLs in one byte are fine.) Read the byte through the image instead.
#include <iecoop/io/located.hpp>
using namespace iecoop;
struct GVL_IO {
  [[no_unique_address]] located<BOOL, "%IX0.5"> bStart;
  [[no_unique_address]] located<BOOL, "%IX0.6"> bStop;
#ifdef IECOOP_COMPILE_FAIL
  [[no_unique_address]] located<BYTE, "%IB0"> byInputs;  // byInputs AT %IB0 : BYTE;
#else
  [[no_unique_address]] located<BYTE, "%IB1"> byInputs;  // byInputs AT %IB1 : BYTE;
#endif
  using LOCATED = pins<&GVL_IO::bStart, &GVL_IO::bStop, &GVL_IO::byInputs>;
};
int main() {
  check_located<GVL_IO>();
  GVL_IO io;
  const BYTE all = default_process_image::read<BYTE, "%IB0">();  // the deliberate alias
  return (io.bStart & io.bStop) == TRUE || all != 0 || io.byInputs != 0 ? 1 : 0;
}
