// modbus_client against a Modbus server not written here: Debian's python3-pymodbus, as the
// simulated remote I/O coupler tests/exchange/remote_io.py (its inputs follow its outputs), started
// on localhost. Also the failures a controller meets: the device killed and started again, an
// exception response, a device too slow for its timeout, a device that is not there.
#include <doctest/doctest.h>

#include <chrono>
#include <cstdint>
#include <string>
#include <thread>
#include <vector>

#include <iecoop/exchange/modbus_client.hpp>
#include <iecoop/iecoop.hpp>

#include "peer.hpp"
#include "running.hpp"

using namespace iecoop;
using namespace exchange_test;

namespace {

struct client_tag {};
using client_image = process_image<64, 64, 16, addressing::codesys, client_tag>;

// PROGRAM IO_PRG
// VAR
//     wSetpoint AT %QW0 : WORD;  wSpeed AT %QW1 : WORD;    (the coupler's holding registers 0, 1)
//     bValve AT %QX8.3 : BOOL;                             (its coil 3)
//     wSetpointBack AT %IW0 : WORD; wSpeedBack AT %IW1 : WORD;  (its input registers 0, 1: wired back)
//     bValveBack AT %IX8.3 : BOOL;                         (its discrete input 3: wired back)
//     wCounter AT %IW10 : WORD;                            (its input register 20: live)
//     wCommand : WORD; xValve : BOOL;
// END_VAR
struct IO_PRG : program<IO_PRG> {
  [[no_unique_address]] located<WORD, "%QW0", client_image> wSetpoint;
  [[no_unique_address]] located<WORD, "%QW1", client_image> wSpeed;
  [[no_unique_address]] located<BOOL, "%QX8.3", client_image> bValve;
  [[no_unique_address]] located<WORD, "%IW0", client_image> wSetpointBack;
  [[no_unique_address]] located<WORD, "%IW1", client_image> wSpeedBack;
  [[no_unique_address]] located<BOOL, "%IX8.3", client_image> bValveBack;
  [[no_unique_address]] located<WORD, "%IW10", client_image> wCounter;
  WORD wCommand;
  BOOL xValve;
  using LOCATED = pins<&IO_PRG::wSetpoint, &IO_PRG::wSpeed, &IO_PRG::bValve, &IO_PRG::wSetpointBack,
                       &IO_PRG::wSpeedBack, &IO_PRG::bValveBack, &IO_PRG::wCounter>;
  void body() {
    wSetpoint = wCommand;   // wSetpoint := wCommand;
    wSpeed = wCommand + 1;  // wSpeed := wCommand + 1;
    bValve = xValve;        // bValve := xValve;
  }
};

using client_app = application<task<IO_PRG>, use_image<client_image>>;

client_app make_app() {
  return client_app{iecoop::task<IO_PRG>{"Fast", cyclic{"T#1ms"_iec}, 0, watchdog{"T#300ms"_iec, 1}},
                    use_image<client_image>{}};
}

std::vector<std::string> remote_io(std::uint16_t port, std::vector<std::string> options = {}) {
  std::vector<std::string> argv{IECOOP_PYTHON3, IECOOP_EXCHANGE_DIR "/remote_io.py", std::to_string(port)};
  argv.insert(argv.end(), options.begin(), options.end());
  return argv;
}

// The coupler, as a device of the client.
modbus_device_config coupler(std::uint16_t port) {
  modbus_device_config d;
  d.name = "Coupler1";
  d.port = port;
  d.poll_interval = "LTIME#10ms"_iec;
  d.response_timeout = "LTIME#200ms"_iec;
  d.reconnect_delay = "LTIME#20ms"_iec;
  d.reconnect_delay_max = "LTIME#200ms"_iec;
  d.reads = {
      {.table = modbus_table::input_registers, .remote = 0, .count = 2, .image = "%IW0", .safe = {7, 8}},
      {.table = modbus_table::discrete_inputs, .remote = 0, .count = 8, .image = "%IX8.0", .safe = {0, 0, 0, 1}},
      {.table = modbus_table::input_registers,
       .remote = 20,
       .count = 1,
       .image = "%IW10",
       .on_error = modbus_error_value::keep_last},
  };
  d.writes = {
      {.table = modbus_table::holding_registers, .remote = 0, .count = 2, .image = "%QW0"},
      {.table = modbus_table::coils, .remote = 0, .count = 8, .image = "%QX8.0"},
  };
  return d;
}

// The device serves (pymodbus takes a second or two to start).
void wait_until_serving(const peer& device, std::uint16_t port) {
  REQUIRE_MESSAGE(device.wait_for_output("serving on", 20s), device.output());
  REQUIRE(wait_for_port(port, 10s));  // (pymodbus says so a moment before it listens)
}

// The client polls, connected to the application, which runs.
void start_polling(client_app& plc, modbus_client<client_image>& client) {
  REQUIRE(client.start() == nullptr);
  plc.connect(client);
  REQUIRE(plc.start());
}

// A pymodbus coupler on a free port (started with `options`), and the application whose client
// polls it (coupler(port), changed by `adjust`), started.
struct coupler_rig {
  explicit coupler_rig(std::vector<std::string> options = {}, void (*adjust)(modbus_device_config&) = nullptr)
      : device(remote_io(port, std::move(options))), client({configured(port, adjust)}) {
    wait_until_serving(device, port);
    start_polling(plc, client);
  }

  std::uint16_t port = free_port();
  peer device;
  client_app plc = make_app();
  modbus_client<client_image> client;

 private:
  static modbus_device_config configured(std::uint16_t port, void (*adjust)(modbus_device_config&)) {
    modbus_device_config d = coupler(port);
    if (adjust != nullptr) adjust(d);
    return d;
  }
};

// Runs cycles in simulated time, each followed by a real millisecond, until `condition` holds
// between two cycles (at most `timeout`).
template <class App, class Condition>
bool run_until(App& plc, Condition condition, std::chrono::milliseconds timeout = 20s) {
  const auto until = std::chrono::steady_clock::now() + timeout;
  while (std::chrono::steady_clock::now() < until) {
    plc.run_for("T#1ms"_iec);
    if (condition()) return true;
    std::this_thread::sleep_for(1ms);
  }
  return false;
}

}  // namespace

TEST_CASE("modbus_client: outputs reach a pymodbus coupler, its inputs come back into %I, with the device's status") {
  coupler_rig rig;
  client_app& plc = rig.plc;
  modbus_client<client_image>& client = rig.client;
  IO_PRG& prg = plc.get<IO_PRG>();

  prg.wCommand = 4242;
  prg.xValve = TRUE;
  REQUIRE(run_until(plc, [&] { return prg.wSetpointBack == 4242 && prg.wSpeedBack == 4243; }));
  REQUIRE(run_until(plc, [&] { return prg.bValveBack == TRUE && client.status(0).xError == FALSE; }));
  const modbus_device_status& s = client.status(0);
  CHECK(s.xConnected == TRUE);
  CHECK(s.udiConnects == 1);
  CHECK(s.udiErrors == 0);
  CHECK(s.byModbusError == 0);
  CHECK(s.udiPolls >= 1);

  prg.xValve = FALSE;
  REQUIRE(run_until(plc, [&] { return prg.bValveBack == FALSE; }));
  const WORD counter = prg.wCounter;
  REQUIRE(run_until(plc, [&] { return prg.wCounter != counter; }));  // live data from the device
  CHECK(client.status(0).udiErrors == 0);
}

TEST_CASE(
    "modbus_client: the device killed mid-run, then started again: error values, diagnostics, reconnection by itself") {
  coupler_rig rig;
  peer& device = rig.device;
  const std::uint16_t port = rig.port;
  client_app& plc = rig.plc;
  modbus_client<client_image>& client = rig.client;
  IO_PRG& prg = plc.get<IO_PRG>();
  prg.wCommand = 100;
  REQUIRE(run_until(plc, [&] { return prg.wSetpointBack == 100 && prg.wCounter != 0; }));
  const WORD last_counter = prg.wCounter;

  device.kill(SIGKILL);
  REQUIRE(run_until(plc, [&] { return client.status(0).xConnected == FALSE; }));
  // The poll that finds the connection gone keeps what it read before (a channel read in full
  // is good data); the next, which cannot connect, gives every channel its error value.
  REQUIRE(run_until(plc, [&] { return client.status(0).xError == TRUE && prg.wSetpointBack == 7; }));
  CHECK(prg.wSetpointBack == 7);  // safe values
  CHECK(prg.wSpeedBack == 8);
  CHECK(prg.bValveBack == TRUE);
  CHECK(prg.wCounter >= last_counter);  // keep_last: the last value read
  CHECK(prg.wCounter != 0);
  const UDINT errors = client.status(0).udiErrors;
  REQUIRE(run_until(plc, [&] { return client.status(0).udiErrors > errors + 2; }));  // it keeps trying

  device.start();  // the same port again
  wait_until_serving(device, port);
  prg.wCommand = 200;
  REQUIRE(run_until(
      plc, [&] { return client.status(0).xConnected == TRUE && prg.wSetpointBack == 200; }, 30s));
  REQUIRE(run_until(plc, [&] { return client.status(0).xError == FALSE; }));
  CHECK(client.status(0).udiConnects == 2);
  CHECK(prg.wSpeedBack == 201);
}

TEST_CASE("modbus_client: an exception response fails its channel only, and is shown with its code") {
  coupler_rig rig({"--size", "30"}, [](modbus_device_config& d) {
    // Input registers 28..31 of a device that has 0..29: exception 2, illegal data address.
    d.reads.push_back(
        {.table = modbus_table::input_registers, .remote = 28, .count = 4, .image = "%IW20", .safe = {0xDEAD, 0xBEEF}});
  });
  client_app& plc = rig.plc;
  modbus_client<client_image>& client = rig.client;
  IO_PRG& prg = plc.get<IO_PRG>();
  prg.wCommand = 31;
  REQUIRE(run_until(plc, [&] { return prg.wSetpointBack == 31 && client.status(0).udiExceptions >= 3; }));
  const modbus_device_status& s = client.status(0);
  CHECK(s.byModbusError == 2);
  CHECK(s.xError == TRUE);
  CHECK(s.xConnected == TRUE);
  CHECK(s.udiConnects == 1);  // an exception is an answer: the connection stays
  CHECK(s.udiTimeouts == 0);
  CHECK(client_image::read<WORD, "%IW20">() == 0xDEAD);
  CHECK(client_image::read<WORD, "%IW21">() == 0xBEEF);
  CHECK(client_image::read<WORD, "%IW22">() == 0);
}

TEST_CASE("modbus_client: a device slower than its timeout fails with timeouts, the task never waits for it") {
  coupler_rig rig({"--delay", "1.0"}, [](modbus_device_config& d) { d.response_timeout = "LTIME#400ms"_iec; });
  client_app& plc = rig.plc;
  modbus_client<client_image>& client = rig.client;
  {
    // Real time, 1 ms cycles, watchdog 300 ms: a cycle that waited for the device would wait
    // its 400 ms timeout and fault. (300 ms leave room for a machine busy with other tests.)
    running cycles(plc);
    std::this_thread::sleep_for(2000ms);
  }
  const modbus_device_status& s = client.status(0);
  CHECK(s.udiTimeouts >= 2);
  CHECK(s.xError == TRUE);
  CHECK(s.byModbusError == 0);
  CHECK(plc.get<IO_PRG>().wSetpointBack == 7);
  const task_statistics& t = plc.task("Fast").statistics();
  CHECK(t.cycles > 100);
  CHECK(t.watchdog_overruns == 0);
  CHECK(t.max_cycle_time < "LTIME#300ms"_iec);
  CHECK(plc.faulted_task() == nullptr);
}

TEST_CASE("modbus_client: a device that is not there: error values from the start, connection attempts backing off") {
  const std::uint16_t port = free_port();  // nothing listens
  client_app plc = make_app();
  modbus_client<client_image> client{{coupler(port)}};
  start_polling(plc, client);
  REQUIRE(run_until(plc, [&] { return client.status(0).udiErrors >= 2; }));
  const auto started = std::chrono::steady_clock::now();
  const UDINT errors = client.status(0).udiErrors;
  run_until(
      plc, [] { return false; }, 1000ms);
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count();
  // 20 ms doubling up to 200 ms: about 5 to 8 attempts a second, not one per 10 ms poll.
  const auto attempts = (client.status(0).udiErrors - errors).value();
  CHECK(attempts >= 2);
  CHECK(static_cast<double>(attempts) <= 12 * seconds);
  CHECK(client.status(0).xConnected == FALSE);
  CHECK(client.status(0).udiConnects == 0);
  CHECK(plc.get<IO_PRG>().wSetpointBack == 7);
  CHECK(plc.get<IO_PRG>().bValveBack == TRUE);
}

TEST_CASE("modbus_client: channels that do not fit are refused by start(), naming the device") {
  auto start_with = [](auto change) {
    modbus_device_config d = coupler(502);
    change(d);
    modbus_client<client_image> client{{d}};
    const char* error = client.start();
    return std::string(error == nullptr ? "" : error);
  };
  CHECK(start_with([](modbus_device_config&) {}).empty());
  // No default place in the image: each channel's must be given.
  CHECK(modbus_channel{}.image.empty());
  CHECK(start_with([](modbus_device_config& d) {
          d.reads[1].image.clear();
        }).find("read channel's image is not given") != std::string::npos);
  CHECK(start_with([](modbus_device_config& d) {
          d.writes[1].image.clear();
        }).find("write channel's image is not given") != std::string::npos);
  CHECK(start_with([](modbus_device_config& d) { d.writes[0].image = "%IW4"; }).find("%Q address") !=
        std::string::npos);
  CHECK(start_with([](modbus_device_config& d) { d.reads[0].image = "%QW4"; }).find("%I address") != std::string::npos);
  CHECK(start_with([](modbus_device_config& d) {
          d.writes[0].table = modbus_table::input_registers;
        }).find("read only") != std::string::npos);
  CHECK(start_with([](modbus_device_config& d) { d.reads[0].count = 126; }).find("125 registers") != std::string::npos);
  CHECK(start_with([](modbus_device_config& d) { d.reads[2].image = "%IW1"; }).find("same input bits") !=
        std::string::npos);
  CHECK(start_with([](modbus_device_config& d) { d.reads[1].image = "%IW2"; }).find("bit address") !=
        std::string::npos);
  CHECK(start_with([](modbus_device_config& d) { d.unit_id = 250; }).find("0..247 or 255") != std::string::npos);
  CHECK(start_with([](modbus_device_config& d) { d.unit_id = 255; }).empty());
  CHECK(start_with([](modbus_device_config& d) { d.response_timeout = LTIME{}; }).find("at least 1 ms") !=
        std::string::npos);
  const std::string host = start_with([](modbus_device_config& d) { d.host = "coupler.local"; });
  CHECK(host.find("IPv4") != std::string::npos);
  CHECK(host.find("(device Coupler1)") != std::string::npos);
  // Beside another driver in an io_chain: the read channels are its input footprint, the write
  // channels its output footprint.
  modbus_client<client_image> one{{coupler(502)}};
  REQUIRE(one.input_footprint().size() == 3);
  CHECK(one.input_footprint()[1] == window_of<"%IX8.0", 8, client_image>);
  CHECK(one.output_footprint()[0] == window_of<"%QW0", 2, client_image>);
  simulated_io<client_image> card{window_of<"%IB8", 1, client_image>};  // the card's %IB8: the coupler's bits
  io_chain io{card, one};
  CHECK(std::string(io.configuration_error()) ==
        "iecoop: io_chain: drivers 1 (simulated_io) and 2 (modbus_client) both write %IB8; give each driver its own "
        "input area");
  simulated_io<client_image> other_card{window_of<"%IB9", 1, client_image>};
  io_chain fine{other_card, one};
  CHECK(fine.configuration_error() == nullptr);
  // Two devices reading into the same bits.
  modbus_client<client_image> two{{coupler(502), coupler(503)}};
  const char* error = two.start();
  REQUIRE(error != nullptr);
  CHECK(std::string(error).find("devices Coupler1 and Coupler1") != std::string::npos);
}
