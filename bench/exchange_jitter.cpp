// Does network traffic move a task's timing? (docs/exchange.md, "Cost")
//
//   iecoop_exchange_jitter [--phases N] [--seconds S] [--clients K] [--words W]
//
// Runs an application in real time (realtime_runner, SCHED_FIFO where permitted): task Fast every
// 1 ms, its program mapped to W holding and W input registers of a modbus_server. Phases of S
// seconds take turns, N of each: "quiet" (no client) and "traffic" (K libmodbus clients in threads
// of their own, each writing all W holding registers and reading all W input registers back to
// back, as fast as the server answers). The program notes the steady clock at each cycle's start;
// per phase the table gives the cycle-to-cycle interval's deviation from 1 ms (median, 99th
// percentile, maximum, in microseconds), the requests served and the watchdog overruns. Prints a
// Markdown table; exits 1 if a cycle overran the watchdog (5 ms).
#include <algorithm>
#include <atomic>
#include <chrono>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <string>
#include <thread>
#include <vector>

#include <iecoop/exchange/modbus_server.hpp>
#include <iecoop/iecoop.hpp>
#include <iecoop/runtime/realtime.hpp>

namespace {

using namespace iecoop;
using clock_type = std::chrono::steady_clock;

struct jitter_tag {};
using image = process_image<256, 256, 16, addressing::codesys, jitter_tag>;

// The cycles' start times of the phase under way (preallocated: the program never allocates).
struct start_log {
  std::vector<clock_type::time_point> times;
  std::size_t count = 0;
};
start_log* current_log = nullptr;

// PROGRAM JITTER_PRG: echoes the holding registers into the input registers and notes the time.
struct JITTER_PRG : program<JITTER_PRG> {
  void body() {
    if (current_log != nullptr && current_log->count < current_log->times.size()) {
      current_log->times[current_log->count++] = clock_type::now();
    }
    std::memcpy(image::outputs().data(), image::inputs().data(), 250);
  }
};

struct phase_result {
  const char* name;
  double p50_us, p99_us, max_us;
  std::size_t cycles;
  std::uint64_t requests;
};

phase_result summarise(const char* name, const start_log& log, std::uint64_t requests) {
  std::vector<double> deviation;
  for (std::size_t i = 1; i < log.count; ++i) {
    const double interval_us = std::chrono::duration<double, std::micro>(log.times[i] - log.times[i - 1]).count();
    deviation.push_back(std::abs(interval_us - 1000.0));
  }
  std::sort(deviation.begin(), deviation.end());
  auto at = [&](double q) {
    return deviation.empty() ? 0.0
                             : deviation[std::min(deviation.size() - 1,
                                                  static_cast<std::size_t>(q * static_cast<double>(deviation.size())))];
  };
  return {name, at(0.5), at(0.99), deviation.empty() ? 0.0 : deviation.back(), log.count, requests};
}

}  // namespace

int main(int argc, char** argv) {
  int phases = 3;
  double seconds = 2.0;
  int clients = 4;
  int words = 125;
  for (int i = 1; i + 1 < argc; i += 2) {
    const std::string option = argv[i];
    if (option == "--phases")
      phases = std::atoi(argv[i + 1]);
    else if (option == "--seconds")
      seconds = std::atof(argv[i + 1]);
    else if (option == "--clients")
      clients = std::atoi(argv[i + 1]);
    else if (option == "--words")
      words = std::atoi(argv[i + 1]);
    else {
      std::fprintf(stderr, "usage: %s [--phases N] [--seconds S] [--clients K] [--words W]\n", argv[0]);
      return 2;
    }
  }
  if (phases < 1 || seconds <= 0 || clients < 1 || words < 1 || words > 125) {
    std::fprintf(stderr, "%s: phases >= 1, seconds > 0, clients >= 1, words 1..125\n", argv[0]);
    return 2;
  }

  application plc{task<JITTER_PRG>{"Fast", cyclic{"T#1ms"_iec}, 0, watchdog{"T#5ms"_iec, 1}}, use_image<image>{}};
  modbus_server_config config;
  config.bind_address = "127.0.0.1";
  config.port = 0;
  config.holding_registers = static_cast<std::uint16_t>(words);
  config.holding_image = "%IW0";
  config.input_registers = static_cast<std::uint16_t>(words);
  config.max_clients = clients + 1;
  modbus_server<image> server{config};
  if (const char* error = server.start()) {
    std::fprintf(stderr, "%s\n", error);
    return 1;
  }
  plc.connect(server);
  plc.start();
  realtime_runner runner{plc, {.fifo = true}};

  std::vector<phase_result> results;
  std::atomic<bool> never{false};
  for (int p = 0; p < 2 * phases; ++p) {
    const bool traffic = p % 2 == 1;
    start_log log;
    log.times.resize(static_cast<std::size_t>(seconds * 1000 * 1.2) + 100);
    std::atomic<bool> done{false};
    std::vector<std::thread> load;
    if (traffic) {
      for (int c = 0; c < clients; ++c) {
        load.emplace_back([&] {
          detail::modbus_context context(modbus_new_tcp("127.0.0.1", server.port()));
          if (!context || modbus_connect(context.get()) != 0) return;
          std::vector<std::uint16_t> registers(static_cast<std::size_t>(words));
          while (!done.load(std::memory_order_relaxed)) {
            modbus_write_registers(context.get(), 0, words, registers.data());
            modbus_read_input_registers(context.get(), 0, words, registers.data());
            ++registers[0];
          }
        });
      }
      std::this_thread::sleep_for(std::chrono::milliseconds(100));  // the clients are under way
    }
    const std::uint64_t requests_before = server.statistics().requests;
    current_log = &log;
    runner.run(never, LTIME::from_ticks(static_cast<std::uint64_t>(seconds * 1e9)));
    current_log = nullptr;
    done.store(true);
    for (std::thread& t : load) t.join();
    if (traffic) std::this_thread::sleep_for(std::chrono::milliseconds(50));  // the last replies are counted
    const std::uint64_t requests = server.statistics().requests - requests_before;
    results.push_back(summarise(traffic ? "traffic" : "quiet", log, requests));
  }

  const task_statistics& s = plc.task("Fast").statistics();
  std::printf("SCHED_FIFO: %s; %d clients, %d words each way; %d phases of %.1f s each\n\n",
              runner.fifo_active() ? "granted" : "not granted", clients, words, 2 * phases, seconds);
  std::printf("| phase | cycles | requests served | interval deviation p50 (us) | p99 (us) | max (us) |\n");
  std::printf("|---|---:|---:|---:|---:|---:|\n");
  for (const phase_result& r : results) {
    std::printf("| %s | %zu | %llu | %.1f | %.1f | %.1f |\n", r.name, r.cycles,
                static_cast<unsigned long long>(r.requests), r.p50_us, r.p99_us, r.max_us);
  }
  std::printf("\nwatchdog overruns (5 ms): %llu; max cycle time %.1f us\n",
              static_cast<unsigned long long>(s.watchdog_overruns),
              static_cast<double>(s.max_cycle_time.count()) / 1000.0);
  return s.watchdog_overruns == 0 ? 0 : 1;
}
