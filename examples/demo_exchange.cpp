// The demo's network: with --modbus, the conveyor's outputs served to any Modbus client; with
// --mqtt, the trace's values published to a broker and the batch size taken as a command
// (docs/exchange.md; demo.hpp says why this is a file of its own). Built with what CMake found:
// IECOOP_DEMO_MODBUS where libmodbus is installed, IECOOP_DEMO_MQTT where libmosquitto is.
#include "demo.hpp"

#ifndef IECOOP_DEMO_MODBUS
#define IECOOP_DEMO_MODBUS 0
#endif
#ifndef IECOOP_DEMO_MQTT
#define IECOOP_DEMO_MQTT 0
#endif
#if IECOOP_DEMO_MODBUS
#include <iecoop/exchange/modbus_server.hpp>
#endif
#if IECOOP_DEMO_MQTT
#include <iecoop/exchange/mqtt.hpp>
#endif

#include <fmt/core.h>

#include <cstdio>
#include <optional>

namespace demo_host {

const bool built_with_modbus = IECOOP_DEMO_MODBUS != 0;
const bool built_with_mqtt = IECOOP_DEMO_MQTT != 0;

namespace {
using namespace iecoop;
#if IECOOP_DEMO_MODBUS
// CODESYS: a Modbus TCP Slave Device with 8 holding and 4 input registers. Its holding
// registers lie after the terminals (%IB0..%IB3): an io_chain refuses two drivers on one input.
std::optional<modbus_server<>> hmi;
std::optional<io_chain<simulated_io<>, modbus_server<>>> io;
#endif
#if IECOOP_DEMO_MQTT
std::optional<mqtt_bridge<32, 8>> mqtt;
#endif
}  // namespace

bool start_exchange([[maybe_unused]] conveyor_app& plc, [[maybe_unused]] const exchange_options& options) {
#if IECOOP_DEMO_MODBUS
  if (options.modbus_port >= 0) {
    modbus_server_config served;
    served.port = static_cast<std::uint16_t>(options.modbus_port);
    served.holding_registers = 8;
    served.holding_image = "%IW8";
    served.input_registers = 4;
    served.input_image = "%QW0";
    hmi.emplace(served);
    if (const char* error = hmi->start()) {
      fmt::print(stderr, "{}\n", error);
      hmi.reset();
      return false;
    }
    io.emplace(sim::field, *hmi);
    plc.connect(*io);
    fmt::print("  modbus   serving on port {}: input registers 0..3 = %QW0..%QW3, holding registers 0..7 = %IW8..%IW15\n",
               hmi->port());
  }
#endif
#if IECOOP_DEMO_MQTT
  if (!options.mqtt_host.empty()) {
    mqtt_bridge_config broker;
    broker.host = options.mqtt_host;
    broker.port = options.mqtt_port;
    broker.client_id = "iecoop-demo";
    broker.topic_prefix = "iecoop/demo";
    mqtt.emplace(broker);
    add_shift_channels(*mqtt, plc);
    mqtt->command("GVL_Config.wBatchSize", plc.get<demo::GVL_Config>().wBatchSize, WORD(1), WORD(100));
    mqtt->attach(plc.task("Fast"));
    if (const char* error = mqtt->start()) {
      fmt::print(stderr, "{}\n", error);
      mqtt.reset();
      return false;
    }
    fmt::print("  mqtt     {}:{}: iecoop/demo/<name>, iecoop/demo/status; command iecoop/demo/GVL_Config/wBatchSize/set\n",
               options.mqtt_host, options.mqtt_port);
  }
#endif
  return true;
}

void stop_exchange([[maybe_unused]] conveyor_app& plc) {
#if IECOOP_DEMO_MODBUS
  if (hmi) {
    const modbus_server_statistics served = hmi->statistics();
    fmt::print("modbus:  {} requests served ({} answered with an exception), {} connections\n", served.requests,
               served.exceptions, served.connections);
    hmi->stop();
    plc.connect(sim::field);
    io.reset();
    hmi.reset();
  }
#endif
#if IECOOP_DEMO_MQTT
  if (mqtt) {
    mqtt->stop();  // "offline", then disconnect
    const mqtt_bridge_statistics sent = mqtt->statistics();
    fmt::print("mqtt:    {} messages published, {} commands applied ({} rejected), {} connections\n", sent.published,
               sent.commands_applied, sent.commands_rejected, sent.connects);
    mqtt.reset();
  }
#endif
}

}  // namespace demo_host
