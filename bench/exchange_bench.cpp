// The data exchange's cost to the task cycle (docs/exchange.md, "Cost"): what a driver's
// read_inputs (the latch at the cycle's start) and write_outputs (the publication at its end)
// take, by the number of mapped 16-bit words.
//
//   BM_ModbusServerCycle/<words>       modbus_server with <words> holding and <words> input
//                                      registers, serving, no client: ns per cycle, per word
//   BM_ModbusServerCycleBusy/<words>   the same while a libmodbus client in another thread reads
//                                      and writes every register back to back (each latch finds
//                                      a new snapshot, the cache lines move between threads)
//   BM_ModbusClientCycle/<words>       modbus_client with one device of <words> read and
//                                      <words> written registers (its poller finds no device and
//                                      backs off: the cycle side is the same)
//   BM_MqttTaskCycle/<channels>        a 1 ms task cycle in simulated time (the scheduler, a program
//                                      that changes <channels> INTs) with an mqtt_bridge attached that
//                                      publishes them (not started: the capture after the cycle and
//                                      the command check before it are the same)
//   BM_MqttTaskCycleBaseline/<channels> the same task without the bridge: the difference is the bridge's
#include <benchmark/benchmark.h>

#include <array>
#include <atomic>
#include <cstddef>
#include <cstdint>
#include <string>
#include <thread>
#include <vector>

#include <iecoop/exchange/modbus_client.hpp>
#include <iecoop/exchange/modbus_server.hpp>
#include <iecoop/exchange/mqtt.hpp>
#include <iecoop/iecoop.hpp>

namespace {

using namespace iecoop;

struct bench_tag {};
using image = process_image<256, 256, 16, addressing::codesys, bench_tag>;

modbus_server_config server_config(std::uint16_t words) {
  modbus_server_config config;
  config.bind_address = "127.0.0.1";
  config.port = 0;
  config.holding_registers = words;
  config.holding_image = "%IW0";
  config.input_registers = words;
  return config;
}

// The counters of every benchmark here (the CSV reporter wants the same in each).
void count_words(benchmark::State& state, std::uint16_t words) {
  state.counters["words"] = words;
  state.counters["ns_per_word"] = benchmark::Counter(static_cast<double>(state.iterations()) * words,
                                                     benchmark::Counter::kIsRate | benchmark::Counter::kInvert);
}

void BM_ModbusServerCycle(benchmark::State& state) {
  const auto words = static_cast<std::uint16_t>(state.range(0));
  modbus_server<image> server{server_config(words)};
  if (const char* error = server.start()) {
    state.SkipWithError(error);
    return;
  }
  for (auto _ : state) {
    server.read_inputs(image::inputs());
    benchmark::ClobberMemory();
    server.write_outputs(image::outputs());
    benchmark::ClobberMemory();
  }
  count_words(state, words);
}
BENCHMARK(BM_ModbusServerCycle)->Arg(1)->Arg(16)->Arg(64)->Arg(125);

void BM_ModbusServerCycleBusy(benchmark::State& state) {
  const auto words = static_cast<std::uint16_t>(state.range(0));
  modbus_server<image> server{server_config(words)};
  if (const char* error = server.start()) {
    state.SkipWithError(error);
    return;
  }
  std::atomic<bool> done{false};
  std::thread client([&] {
    detail::modbus_context context(modbus_new_tcp("127.0.0.1", server.port()));
    if (!context || modbus_connect(context.get()) != 0) return;
    std::vector<std::uint16_t> registers(words);
    while (!done.load(std::memory_order_relaxed)) {
      modbus_write_registers(context.get(), 0, words, registers.data());
      modbus_read_input_registers(context.get(), 0, words, registers.data());
      ++registers[0];
    }
  });
  for (auto _ : state) {
    server.read_inputs(image::inputs());
    benchmark::ClobberMemory();
    server.write_outputs(image::outputs());
    benchmark::ClobberMemory();
  }
  done.store(true);
  client.join();
  count_words(state, words);
  state.SetLabel(std::to_string(server.statistics().requests) + " requests served");
}
BENCHMARK(BM_ModbusServerCycleBusy)->Arg(16)->Arg(125)->UseRealTime();

void BM_ModbusClientCycle(benchmark::State& state) {
  const auto words = static_cast<std::uint16_t>(state.range(0));
  modbus_device_config device;
  device.port = 9;  // discard: nothing answers Modbus there
  device.reconnect_delay = "LTIME#1s"_iec;
  device.reads = {{.table = modbus_table::input_registers, .remote = 0, .count = words, .image = "%IW0"}};
  device.writes = {{.table = modbus_table::holding_registers, .remote = 0, .count = words, .image = "%QW0"}};
  modbus_client<image> client{{device}};
  if (const char* error = client.start()) {
    state.SkipWithError(error);
    return;
  }
  for (auto _ : state) {
    client.read_inputs(image::inputs());
    benchmark::ClobberMemory();
    client.write_outputs(image::outputs());
    benchmark::ClobberMemory();
  }
  count_words(state, words);
}
BENCHMARK(BM_ModbusClientCycle)->Arg(1)->Arg(16)->Arg(64)->Arg(123);

// PROGRAM VALUES_PRG: 64 INTs, each changed every cycle.
struct VALUES_PRG : program<VALUES_PRG> {
  std::array<INT, 64> aValues{};
  void body() {
    for (INT& v : aValues) v = v + 1;
  }
};

template <bool Bridge>
void mqtt_task_cycle(benchmark::State& state) {
  const auto channels = static_cast<std::size_t>(state.range(0));
  application plc{task<VALUES_PRG>{"Fast", cyclic{"T#1ms"_iec}, 0}};
  plc.start();
  mqtt_bridge<64, 1> bridge{{.topic_prefix = "bench"}};
  static const std::array<std::string, 64> names = [] {
    std::array<std::string, 64> n;
    for (std::size_t i = 0; i < n.size(); ++i) n[i] = "iValue" + std::to_string(i);
    return n;
  }();
  if constexpr (Bridge) {
    for (std::size_t i = 0; i < channels; ++i) bridge.add("VALUES_PRG", names[i], plc.get<VALUES_PRG>().aValues[i]);
    bridge.attach(plc.task("Fast"));
  }
  for (auto _ : state) plc.run_for("T#1ms"_iec);
  count_words(state, static_cast<std::uint16_t>(channels));  // (a channel counts as a word: the same counters)
}
void BM_MqttTaskCycle(benchmark::State& state) { mqtt_task_cycle<true>(state); }
void BM_MqttTaskCycleBaseline(benchmark::State& state) { mqtt_task_cycle<false>(state); }
BENCHMARK(BM_MqttTaskCycle)->Arg(1)->Arg(16)->Arg(64);
BENCHMARK(BM_MqttTaskCycleBaseline)->Arg(1)->Arg(16)->Arg(64);

}  // namespace
