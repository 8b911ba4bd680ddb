// A consumer of the installed package's data exchange (iecoop::modbus, iecoop::mqtt): a Modbus
// server on the image serves (on a free port of 127.0.0.1) and stops; an MQTT bridge is made.
#include <iecoop/exchange/modbus_server.hpp>
#include <iecoop/exchange/mqtt.hpp>
#include <iecoop/iecoop.hpp>

#include <cstdio>

int main() {
  using namespace iecoop;
  modbus_server_config config;
  config.bind_address = "127.0.0.1";
  config.port = 0;
  config.holding_image = "%IW0";  // the holding registers' first input word (no default)
  modbus_server<> server{config};
  if (const char* error = server.start()) {
    std::puts(error);
    return 1;
  }
  const bool serving = server.serving() && server.port() != 0;
  server.stop();
  mqtt_bridge<> bridge{{.host = "127.0.0.1", .client_id = "consumer", .topic_prefix = "consumer"}};
  BOOL bLamp;
  const bool added = bridge.add("bLamp", bLamp);
  return serving && added ? 0 : 1;
}
