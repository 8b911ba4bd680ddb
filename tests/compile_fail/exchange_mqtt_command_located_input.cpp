// EXPECT: iecoop: a %I located variable is written by the I/O driver
// An MQTT command writes a variable at a cycle's start, after the inputs were latched: a %I
// located variable would be overwritten by the driver at the next cycle, so the bridge refuses
// it. The twin commands a %Q located variable. (Checked where libmosquitto is found.)
#include <iecoop/exchange/mqtt.hpp>
#include <iecoop/iecoop.hpp>

using namespace iecoop;
struct IO_PRG : program<IO_PRG> {
  [[no_unique_address]] located<INT, "%IW0"> iwSpeed;
  [[no_unique_address]] located<INT, "%QW0"> qwSpeedRef;
  using LOCATED = pins<&IO_PRG::iwSpeed, &IO_PRG::qwSpeedRef>;
  void body() {}
};
int main() {
  IO_PRG io;
  mqtt_bridge<> mqtt{{.topic_prefix = "line1"}};
#ifdef IECOOP_COMPILE_FAIL
  mqtt.command("IO_PRG.iwSpeed", io.iwSpeed);
#else
  mqtt.command("IO_PRG.qwSpeedRef", io.qwSpeedRef);
#endif
  return 0;
}
