// The iecoop demo: a small machine, written as a PLC engineer would write it in CODESYS, with
// the Structured Text beside each line of C++ (conveyor.hpp: the PLC application and its
// simulation), run here and printed: a trace of the key signals and the tasks' statistics.
//
// The machine is a conveyor that carries parts to a box, with a jam timeout and a motor
// behind an INTERFACE (conveyor.hpp says more). Its tasks run in simulated time (the default:
// 21 s of machine time in a fraction of a second, the same every run) or, with --realtime,
// against the wall clock on iecoop's real-time runner. `iecoop_demo --help` lists the options.
// With --modbus and --mqtt (where the demo was built with libmodbus and libmosquitto) any Modbus
// or MQTT tool can watch the conveyor run (docs/exchange.md). This file holds the command line,
// the run in simulated time; demo_print.cpp prints, demo_realtime.cpp runs it in real time,
// demo_trace.cpp writes the trace's files, demo_exchange.cpp holds the network's glue (demo.hpp).
#include "demo.hpp"

#include <iecoop/fmt.hpp>
#include <iecoop/iecoop.hpp>
#include <iecoop/runtime/file_storage.hpp>
// Set by examples/CMakeLists.txt where the libraries are found.

#include <fmt/core.h>

#include <algorithm>
#include <chrono>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <optional>
#include <string>
#include <string_view>

// ---------------------------------------------------------------------------------------
// Printing, options, main

namespace {

using namespace iecoop;

// Faults are printed and counted, and the demo then ends with exit status 1; a watchdog fault
// also stops the application in its exception state.
unsigned faults = 0;
void on_fault(const fault_info& f) {
  ++faults;
  fmt::print("*** iecoop fault: {}: {}", to_string(f.kind), f.message);
  if (f.task != nullptr) fmt::print(" (task {}{}{})", f.task, f.pou != nullptr ? ", program " : "", f.pou != nullptr ? f.pou : "");
  fmt::print("\n");
}

using demo_host::conveyor_app;
using demo_host::shift_trace;

struct options {
  std::optional<demo::E_Motor> motor;
  bool realtime = false;
  double realtime_seconds = 0.0;  // 0: the whole scenario
  bool fifo = false;
  bool watch = false;
  const char* retain_file = nullptr;
  const char* vcd_file = nullptr;
  const char* csv_file = nullptr;
  const char* svg_file = nullptr;
  demo_host::exchange_options exchange;  // --modbus PORT, --mqtt HOST[:PORT]
  bool help = false;
};

void usage(std::FILE* to) {
  fmt::print(to,
             "usage: iecoop_demo [--motor dol|vfd] [--realtime [SECONDS]] [--fifo] [--retain FILE]\n"
             "                   [--watch] [--vcd FILE] [--csv FILE] [--svg FILE]\n"
             "                   [--modbus PORT] [--mqtt HOST[:PORT]]\n"
             "\n"
             "A conveyor controlled by a PLC program written with iecoop, run against a simulated\n"
             "belt and operator; prints a trace of the key signals and the tasks' statistics.\n"
             "\n"
             "  --motor dol|vfd      the drive wired to the belt: dol, a motor on a contactor (one\n"
             "                       speed), or vfd, a frequency inverter with ramp and speed reference\n"
             "                       (the default). Stored in the PERSISTENT GVL_Config.eMotor.\n"
             "  --realtime [SECONDS] run on the real-time runner against the wall clock for SECONDS\n"
             "                       (default: the whole scenario, {:.0f} s); Ctrl-C stops it.\n"
             "                       Without it, the scenario runs in simulated time.\n"
             "  --fifo               with --realtime: ask for SCHED_FIFO (needs root or CAP_SYS_NICE;\n"
             "                       without it the demo runs as an ordinary thread)\n"
             "  --watch              with --realtime: a watch list of the I/O and the conveyor's values,\n"
             "                       redrawn every 500 ms instead of the trace lines\n"
             "  --retain FILE        keep the RETAIN and PERSISTENT variables in FILE: the counters\n"
             "                       and the drive setting carry over to the next run\n"
             "  --vcd FILE           write the trace of task Fast (I/O, the jam timer, speeds, counts)\n"
             "                       as a VCD file for GTKWave\n"
             "  --csv FILE           ... as CSV (iecoop-replay's format)\n"
             "  --svg FILE           ... as an SVG timing chart a browser shows\n"
             "  --modbus PORT        with --realtime: a Modbus TCP server on PORT (0: a free one): input\n"
             "                       registers 0..3 are %QW0..%QW3 (register 0: bit 0 motor, bit 1 jam\n"
             "                       lamp; register 1: the speed reference), discrete inputs their bits,\n"
             "                       holding registers 0..7 are %IW8..%IW15 (read by nothing here){}\n"
             "  --mqtt HOST[:PORT]   with --realtime: publish the trace's values to the MQTT broker at\n"
             "                       HOST (port 1883) under iecoop/demo/..., on change, retained, with\n"
             "                       iecoop/demo/status online/offline; the batch size is a command:\n"
             "                       iecoop/demo/GVL_Config/wBatchSize/set (1..100){}\n"
             "  --help               this text\n",
             static_cast<double>(LTIME(sim::scenario_length).count()) / 1e9, demo_host::built_with_modbus ? "" : " (not built: libmodbus)",
             demo_host::built_with_mqtt ? "" : " (not built: libmosquitto)");
}

std::optional<options> parse(int argc, char** argv) {
  options o;
  for (int i = 1; i < argc; ++i) {
    const std::string_view arg = argv[i];
    const char* value = i + 1 < argc ? argv[i + 1] : nullptr;
    if (arg == "--help" || arg == "-h") {
      o.help = true;
    } else if (arg == "--motor" && value != nullptr && (value == std::string_view("dol") || value == std::string_view("vfd"))) {
      o.motor = value == std::string_view("dol") ? demo::E_Motor::DOL : demo::E_Motor::VFD;
      ++i;
    } else if (arg == "--realtime") {
      o.realtime = true;
      if (value != nullptr && !std::string_view(value).starts_with("--")) {
        char* end = nullptr;
        o.realtime_seconds = std::strtod(value, &end);
        if (end == value || *end != '\0' || !(o.realtime_seconds > 0.0 && o.realtime_seconds <= 1e6)) return std::nullopt;
        ++i;
      }
    } else if (arg == "--fifo") {
      o.fifo = true;
    } else if (arg == "--watch") {
      o.watch = true;
    } else if (arg == "--retain" && value != nullptr) {
      o.retain_file = value;
      ++i;
    } else if (arg == "--vcd" && value != nullptr) {
      o.vcd_file = value;
      ++i;
    } else if (arg == "--csv" && value != nullptr) {
      o.csv_file = value;
      ++i;
    } else if (arg == "--svg" && value != nullptr) {
      o.svg_file = value;
      ++i;
    } else if (arg == "--modbus" && value != nullptr) {
      char* end = nullptr;
      const long port = std::strtol(value, &end, 10);
      if (end == value || *end != '\0' || port < 0 || port > 65535) return std::nullopt;
      o.exchange.modbus_port = static_cast<int>(port);
      ++i;
    } else if (arg == "--mqtt" && value != nullptr) {
      const std::string_view text = value;
      const std::size_t colon = text.rfind(':');
      o.exchange.mqtt_host = std::string(text.substr(0, colon));
      if (colon != std::string_view::npos) {
        char* end = nullptr;
        const long port = std::strtol(value + colon + 1, &end, 10);
        if (end == value + colon + 1 || *end != '\0' || port < 1 || port > 65535) return std::nullopt;
        o.exchange.mqtt_port = static_cast<std::uint16_t>(port);
      }
      if (o.exchange.mqtt_host.empty()) return std::nullopt;
      ++i;
    } else {
      return std::nullopt;
    }
  }
  if (o.watch && !o.realtime) return std::nullopt;  // a watch list watches a running controller
  // The network watches a running controller too (the simulated shift is over in a blink).
  if ((o.exchange.modbus_port >= 0 || !o.exchange.mqtt_host.empty()) && !o.realtime) return std::nullopt;
  if ((o.exchange.modbus_port >= 0 && !demo_host::built_with_modbus) || (!o.exchange.mqtt_host.empty() && !demo_host::built_with_mqtt)) {
    std::fprintf(stderr, "iecoop_demo: built without %s: install %s and build again\n",
                 o.exchange.modbus_port >= 0 && !demo_host::built_with_modbus ? "libmodbus" : "libmosquitto",
                 o.exchange.modbus_port >= 0 && !demo_host::built_with_modbus ? "libmodbus-dev" : "libmosquitto-dev");
    return std::nullopt;
  }
  return o;
}

int run(const options& opt) {
  using namespace demo;
  using sim::TRACE_PRG;

  auto plc = make_conveyor();  // the tasks, programs and global variable lists (conveyor.hpp)
  plc.connect(sim::field);
  std::optional<file_storage> storage;
  if (opt.retain_file != nullptr) {
    storage.emplace(opt.retain_file);
    plc.use_storage(*storage);
  }
  set_fault_handler(&on_fault);

  plc.start();  // FB_Init of every instance; with --retain, RETAIN and PERSISTENT values come back
  if (opt.motor) plc.get<GVL_Config>().eMotor = *opt.motor;  // commissioning: which drive is fitted
  sim::fitted = plc.get<GVL_Config>().eMotor;

  demo_host::print_banner(plc, opt.realtime, opt.retain_file);  // the machine, its I/O and tasks (demo_print.cpp)
  // --modbus, --mqtt: the conveyor served to Modbus clients, its values published to a broker
  // (demo_exchange.cpp).
  if (!demo_host::start_exchange(plc, opt.exchange)) {
    demo_host::stop_exchange(plc);
    return 1;
  }
  demo_host::print_trace_header();
  std::fflush(stdout);  // the banner now, also into a pipe or a file (a tool waits for the port's line)

  static shift_trace recorder;  // static: 1 MiB is no stack variable
  const bool tracing = opt.vcd_file != nullptr || opt.csv_file != nullptr || opt.svg_file != nullptr;
  if (tracing) {
    demo_host::add_shift_channels(recorder, plc);
    recorder.set_mode(trace_mode::on_change);
    recorder.attach(plc.task("Fast"));
    recorder.start();
  }

  TRACE_PRG& trace = plc.get<TRACE_PRG>();
  const LTIME slice = "LTIME#100ms"_iec;  // print the trace every 100 ms of machine time
  const auto wall_start = std::chrono::steady_clock::now();
  bool fifo_active = false;
  const char* ended = "ran its time";  // --realtime: how the runner ended
  if (!opt.realtime) {
    plc.task("Fast").model_execution_time(&sim::fast_cost);
    plc.task("Slow").model_execution_time(&sim::slow_cost);
    while (plc.now() < LTIME(sim::scenario_length) && plc.state() == application_state::running) {
      plc.run_for(slice);
      demo_host::print_trace(trace);
    }
  } else {
    // --realtime: on iecoop's real-time runner, against the wall clock (demo_realtime.cpp).
    demo_host::realtime_request request;
    request.seconds = opt.realtime_seconds;
    request.fifo = opt.fifo;
    request.watch = opt.watch;
    const demo_host::realtime_result result = demo_host::run_realtime(plc, request, demo_host::print_trace);
    ended = result.ended;
    fifo_active = result.fifo_active;
  }
  const double wall = std::chrono::duration<double>(std::chrono::steady_clock::now() - wall_start).count();

  demo_host::run_summary summary;
  summary.realtime = opt.realtime;
  summary.wall_seconds = wall;
  summary.ended = ended;
  summary.fifo_requested = opt.fifo;
  summary.fifo_active = fifo_active;
  demo_host::print_summary(plc, summary);  // the tasks' statistics, the machine's counts, the times
  if (tracing) {
    recorder.stop();
    const auto report = [&](const char* path, bool (*write)(const shift_trace&, const char*)) {
      if (path != nullptr && !demo_host::print_trace_file(recorder, path, write(recorder, path))) ++faults;
    };
    report(opt.vcd_file, demo_host::write_vcd_file);
    report(opt.csv_file, demo_host::write_csv_file);
    report(opt.svg_file, demo_host::write_svg_file);
  }
  demo_host::stop_exchange(plc);
  plc.stop();  // FB_Exit of every instance; RETAIN and PERSISTENT values saved (to FILE with --retain)
  if (opt.retain_file != nullptr) fmt::print("retain:  saved to {}\n", opt.retain_file);
  return faults == 0 ? 0 : 1;
}

}  // namespace

int main(int argc, char** argv) {
  const std::optional<options> opt = parse(argc, argv);
  if (!opt || opt->help) {
    usage(opt ? stdout : stderr);
    return opt ? 0 : 2;
  }
  return run(*opt);
}
