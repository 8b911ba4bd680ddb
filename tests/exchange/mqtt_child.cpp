// A controller with an MQTT bridge that runs until it is killed, for mqtt_test.cpp's last will:
// `iecoop_mqtt_child <port> <topic prefix>` connects to the broker on 127.0.0.1:<port>, prints
// "connected" once the broker accepted it and its first values are out, and runs a cycle every
// 10 ms (one counter published on change) until SIGKILL ends it without a DISCONNECT.
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <thread>

#include <iecoop/exchange/mqtt.hpp>
#include <iecoop/iecoop.hpp>

using namespace iecoop;

namespace {

// PROGRAM CHILD_PRG: counts its cycles up to 1000, then stays there.
struct CHILD_PRG : program<CHILD_PRG> {
  var<INT> iCount;
  void body() {
    if (iCount < 1000) iCount = iCount + 1;
  }
};

}  // namespace

int main(int argc, char** argv) {
  if (argc != 3) {
    std::fputs("usage: iecoop_mqtt_child <port> <topic prefix>\n", stderr);
    return 2;
  }
  application plc{task<CHILD_PRG>{"Fast", cyclic{"T#10ms"_iec}, 0}};
  plc.start();
  mqtt_bridge<4, 1> mqtt{{.host = "127.0.0.1",
                          .port = static_cast<std::uint16_t>(std::atoi(argv[1])),
                          .client_id = "iecoop-mqtt-child",
                          .topic_prefix = argv[2],
                          .keepalive = 5,
                          .reconnect_min = LTIME::from_ticks(100'000'000),
                          .reconnect_max = LTIME::from_ticks(500'000'000)}};
  mqtt.add("CHILD_PRG", "iCount", plc.get<CHILD_PRG>().iCount);
  mqtt.attach(plc.task("Fast"));
  if (const char* error = mqtt.start()) {
    std::puts(error);
    return 1;
  }
  bool told = false;
  for (;;) {
    plc.run_for("T#10ms"_iec);
    std::this_thread::sleep_for(std::chrono::milliseconds(10));
    const mqtt_bridge_statistics s = mqtt.statistics();
    if (!told && s.connected && s.published >= 2) {  // "online" and the counter
      std::puts("connected");
      std::fflush(stdout);
      told = true;
    }
  }
}
