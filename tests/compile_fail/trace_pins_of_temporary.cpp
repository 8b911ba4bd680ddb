// EXPECT: iecoop: a trace records the pins of a block instance, not of a temporary
// add_pins keeps the addresses of the block's pins: a temporary block is gone after the call.
#include <iecoop/iecoop.hpp>
using namespace iecoop;
int main() {
  TON tJam;
  trace_recorder<1024> trace;
#ifdef IECOOP_COMPILE_FAIL
  trace.add_pins("tJam", TON{});
#else
  trace.add_pins("tJam", tJam);
#endif
}
