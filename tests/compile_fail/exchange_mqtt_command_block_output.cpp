// EXPECT: iecoop: a read_only variable \(a standard block's VAR_OUTPUT\) is written by its block only
// A standard block's VAR_OUTPUT belongs to the block: a command cannot write TON.Q. The twin
// commands the block's input.
#include <iecoop/exchange/mqtt.hpp>
#include <iecoop/iecoop.hpp>

using namespace iecoop;
int main() {
  TON tJam;
  mqtt_bridge<> mqtt{{.topic_prefix = "line1"}};
#ifdef IECOOP_COMPILE_FAIL
  mqtt.command("IO_PRG.tJam.Q", tJam.Q);
#else
  mqtt.command("IO_PRG.tJam.PT", tJam.PT);
#endif
  return 0;
}
