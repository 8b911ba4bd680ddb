// The iecoop demo: a small machine, written as a PLC engineer would write it in CODESYS, with
// the Structured Text beside each line of C++ (conveyor.hpp: the PLC application and its
// simulation), run here and printed: a trace of the key signals and the tasks' statistics.
//
// The machine is a conveyor that carries parts to a box, with a jam timeout and a motor
// behind an INTERFACE (conveyor.hpp says more). Its tasks run in simulated time (the default:
// 21 s of machine time in a fraction of a second, the same every run) or, with --realtime,
// against the wall clock on iecoop's real-time runner. `iecoop_demo --help` lists the options.
// With --modbus and --mqtt (where the demo was built with libmodbus and libmosquitto) any Modbus
// or MQTT tool can watch the conveyor run (docs/exchange.md).
#include "conveyor.hpp"

#include <iecoop/fmt.hpp>
#include <iecoop/iecoop.hpp>
#include <iecoop/runtime/file_storage.hpp>
#include <iecoop/runtime/realtime.hpp>
#include <iecoop/trace/watch.hpp>
// Set by examples/CMakeLists.txt where the libraries are found.
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

#include <algorithm>
#include <atomic>
#include <chrono>
#include <csignal>
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

double seconds(LTIME t) { return static_cast<double>(t.count()) / 1e9; }
double millis(LTIME t) { return static_cast<double>(t.count()) / 1e6; }
const char* bit(BOOL b) { return b ? "1" : "."; }

void print_trace_header() {
  fmt::print("Trace: a line when the operator acts or a key signal changes. parts: the conveyor's CTU\n"
             "(task Fast); total: SUPERVISION_PRG's RETAIN counter (task Slow, every 20 ms); speed: the\n"
             "drive's PROPERTY rSpeed, % of nominal.\n\n");
  fmt::print("{:>6}  {:-^24}   {:-^16}   {:-^17}\n", "", " inputs ", " outputs ", " PLC ");
  fmt::print("{:>6}  {:>5} {:>4} {:>3} {:>5} {:>3} | {:>5} {:>4} {:>5} | {:>5} {:>5} {:>5} | {}\n", "time s", "START",
             "STOP", "EYE", "RESET", "IW1", "MOTOR", "LAMP", "QW1", "speed", "parts", "total", "event");
}

/// Prints the trace lines recorded since the last call.
void print_trace(sim::TRACE_PRG& trace) {
  for (; trace.read < trace.written; ++trace.read) {
    const sim::row& r = trace.rows[trace.read % trace.rows.size()];
    fmt::print("{:6.3f}  {:>5} {:>4} {:>3} {:>5} {:>3} | {:>5} {:>4} {:>5} | {:>5.1f} {:>5} {:>5} | {}\n", seconds(r.time),
               bit(r.start), bit(r.stop), bit(r.eye), bit(r.reset), r.setpoint, bit(r.motor), bit(r.lamp), r.reference, r.speed,
               r.parts, r.total, r.events);
  }
  if (trace.lost > 0) {
    fmt::print("        ({} trace lines lost)\n", trace.lost);
    trace.lost = 0;
  }
}

template <class App>
void print_statistics(const App& plc) {
  fmt::print("\n{:27}{:-^33}  {:-^17}\n", "", " cycle time [ms] ", " jitter [ms] ");
  fmt::print("{:<5} {:>5} {:>4} {:>7}  {:>7} {:>7} {:>7} {:>7}  {:>8} {:>8}  {:>8} {:>8}\n", "task", "every", "prio", "cycles",
             "last", "min", "avg", "max", "min", "max", "overruns", "watchdog");
  std::string watchdogs;
  for (const task_state& t : plc.tasks()) {
    const task_statistics& s = t.statistics();
    fmt::print("{:<5} {:>2} ms {:>4} {:>7}  {:>7.3f} {:>7.3f} {:>7.3f} {:>7.3f}  {:>8.3f} {:>8.3f}  {:>8} {:>8}\n", t.name(),
               millis(t.interval()), t.priority(), s.cycles, millis(s.last_cycle_time), millis(s.min_cycle_time),
               millis(s.average_cycle_time()), millis(s.max_cycle_time), millis(s.min_jitter), millis(s.max_jitter), s.overruns,
               s.watchdog_overruns);
    if (t.settings().has_watchdog) {
      watchdogs += fmt::format("{}{} {} x {}", watchdogs.empty() ? "" : ", ", t.name(), LTIME_TO_TIME(t.settings().watchdog_time),
                               t.settings().watchdog_sensitivity);
    }
  }
  fmt::print("(times in ms; a cycle time runs from the cycle's start to its end, preemption included;\n"
             " overruns: releases skipped because the cycle before had not ended; watchdog: cycles\n"
             " longer than the watchdog time, {})\n",
             watchdogs);
}

// Ctrl-C in --realtime: the runner looks at this flag at least every 50 ms and returns.
std::atomic<bool> stop_requested{false};
static_assert(std::atomic<bool>::is_always_lock_free);
void on_sigint(int) { stop_requested.store(true); }

// Faults are printed and counted, and the demo then ends with exit status 1; a watchdog fault
// also stops the application in its exception state.
unsigned faults = 0;
void on_fault(const fault_info& f) {
  ++faults;
  fmt::print("*** iecoop fault: {}: {}", to_string(f.kind), f.message);
  if (f.task != nullptr) fmt::print(" (task {}{}{})", f.task, f.pou != nullptr ? ", program " : "", f.pou != nullptr ? f.pou : "");
  fmt::print("\n");
}

// The trace of the shift (CODESYS Trace on task Fast, record condition "on change"): the I/O,
// the conveyor's jam timer, the speed setpoint (a PROPERTY), the speed and the part counts.
// 1 MiB holds the whole 21 s shift; written with --vcd, --csv, --svg after the run.
using shift_trace = trace_recorder<1024 * 1024, 32>;

// The values the trace records and the watch list shows.
template <class Channels, class App>
void add_shift_channels(Channels& channels, App& plc) {
  using namespace demo;
  const IO_PRG& io = plc.template get<IO_PRG>();
  const GVL& gvl = plc.template get<GVL>();
  channels.add_located("GVL_IO", plc.template get<GVL_IO>());         // the 8 located variables
  channels.add_pins("IO_PRG.fbConveyor.tJam", io.fbConveyor.tJam);    // IN, PT, Q, ET
  channels.add("IO_PRG.fbConveyor", "rSpeed", io.fbConveyor.rSpeed);  // PROPERTY: the setpoint
  channels.add("GVL", "rSpeed", gvl.rSpeed);                          // the speed now
  channels.add("GVL", "bAtSpeed", gvl.bAtSpeed);
  channels.add("GVL", "wParts", gvl.wParts);
  channels.add("SUPERVISION_PRG", "udiParts", plc.template get<SUPERVISION_PRG>().udiParts);
}

// Writes the trace to `path` with `write(view, put)`; FALSE if the file could not be written.
template <class Write>
bool write_trace(const shift_trace& trace, const char* path, Write write) {
  std::FILE* file = std::fopen(path, "wb");
  if (file == nullptr) return false;
  bool good = true;
  write(trace.view(), [&](std::string_view text) { good = good && std::fwrite(text.data(), 1, text.size(), file) == text.size(); });
  return std::fclose(file) == 0 && good;
}

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
  int modbus_port = -1;             // --modbus PORT
  std::string mqtt_host;            // --mqtt HOST[:PORT]
  std::uint16_t mqtt_port = 1883;
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
             seconds(LTIME(sim::scenario_length)), IECOOP_DEMO_MODBUS ? "" : " (not built: libmodbus)",
             IECOOP_DEMO_MQTT ? "" : " (not built: libmosquitto)");
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
      o.modbus_port = static_cast<int>(port);
      ++i;
    } else if (arg == "--mqtt" && value != nullptr) {
      const std::string_view text = value;
      const std::size_t colon = text.rfind(':');
      o.mqtt_host = std::string(text.substr(0, colon));
      if (colon != std::string_view::npos) {
        char* end = nullptr;
        const long port = std::strtol(value + colon + 1, &end, 10);
        if (end == value + colon + 1 || *end != '\0' || port < 1 || port > 65535) return std::nullopt;
        o.mqtt_port = static_cast<std::uint16_t>(port);
      }
      if (o.mqtt_host.empty()) return std::nullopt;
      ++i;
    } else {
      return std::nullopt;
    }
  }
  if (o.watch && !o.realtime) return std::nullopt;  // a watch list watches a running controller
  // The network watches a running controller too (the simulated shift is over in a blink).
  if ((o.modbus_port >= 0 || !o.mqtt_host.empty()) && !o.realtime) return std::nullopt;
  if ((o.modbus_port >= 0 && !IECOOP_DEMO_MODBUS) || (!o.mqtt_host.empty() && !IECOOP_DEMO_MQTT)) {
    std::fprintf(stderr, "iecoop_demo: built without %s: install %s and build again\n",
                 o.modbus_port >= 0 && !IECOOP_DEMO_MODBUS ? "libmodbus" : "libmosquitto",
                 o.modbus_port >= 0 && !IECOOP_DEMO_MODBUS ? "libmodbus-dev" : "libmosquitto-dev");
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
  GVL_Config& config = plc.get<GVL_Config>();
  if (opt.motor) config.eMotor = *opt.motor;  // commissioning: which drive is fitted
  sim::fitted = config.eMotor;
  const bool dol = config.eMotor == E_Motor::DOL;

  fmt::print("iecoop {}.{}.{} demo: a conveyor with a jam timeout, {}\n\n", IECOOP_VERSION_MAJOR, IECOOP_VERSION_MINOR,
             IECOOP_VERSION_PATCH, opt.realtime ? "in real time" : "in simulated time");
  fmt::print("  inputs   %IX0.0 START (NO)  %IX0.1 STOP (NC)  %IX0.2 photo eye  %IX0.3 RESET  %IW1 speed %\n");
  fmt::print("  outputs  %QX0.0 {}  %QX0.1 jam lamp  %QW1 speed reference (16#4000 = 100 %)\n",
             dol ? "contactor" : "drive enable");
  fmt::print("  drive    {}, batches of {} parts, jam after T#2s at the eye\n",
             dol ? "DOL (FB_DolMotor: on or off, 100 %)" : "VFD (FB_VfdMotor: ramp T#1s, 20..100 %)", config.wBatchSize);
  fmt::print("  tasks    Sim 1 ms (operator, belt, trace)  Fast 1 ms: IO_PRG  Slow 20 ms: SUPERVISION_PRG\n");
  if (opt.retain_file != nullptr) {
    const SUPERVISION_PRG& s = plc.get<SUPERVISION_PRG>();
    fmt::print("  retain   {}: parts {}, jams {} from the runs before\n", opt.retain_file, s.udiParts, s.uiJams);
  }
#if IECOOP_DEMO_MODBUS
  // --modbus: the conveyor's outputs served to any Modbus client, beside the simulated field
  // (CODESYS: a Modbus TCP Slave Device with 8 holding and 4 input registers). Its holding
  // registers lie after the terminals (%IB0..%IB3): an io_chain refuses two drivers on one input.
  std::optional<modbus_server<>> hmi;
  std::optional<io_chain<simulated_io<>, modbus_server<>>> io;
  if (opt.modbus_port >= 0) {
    modbus_server_config served;
    served.port = static_cast<std::uint16_t>(opt.modbus_port);
    served.holding_registers = 8;
    served.holding_image = "%IW8";
    served.input_registers = 4;
    served.input_image = "%QW0";
    hmi.emplace(served);
    if (const char* error = hmi->start()) {
      fmt::print(stderr, "{}\n", error);
      return 1;
    }
    io.emplace(sim::field, *hmi);
    plc.connect(*io);
    fmt::print("  modbus   serving on port {}: input registers 0..3 = %QW0..%QW3, holding registers 0..7 = %IW8..%IW15\n",
               hmi->port());
  }
#endif
#if IECOOP_DEMO_MQTT
  // --mqtt: the trace's values published on change; the batch size as a command.
  std::optional<mqtt_bridge<32, 8>> mqtt;
  if (!opt.mqtt_host.empty()) {
    mqtt_bridge_config broker;
    broker.host = opt.mqtt_host;
    broker.port = opt.mqtt_port;
    broker.client_id = "iecoop-demo";
    broker.topic_prefix = "iecoop/demo";
    mqtt.emplace(broker);
    add_shift_channels(*mqtt, plc);
    mqtt->command("GVL_Config.wBatchSize", config.wBatchSize, WORD(1), WORD(100));
    mqtt->attach(plc.task("Fast"));
    if (const char* error = mqtt->start()) {
      fmt::print(stderr, "{}\n", error);
      return 1;
    }
    fmt::print("  mqtt     {}:{}: iecoop/demo/<name>, iecoop/demo/status; command iecoop/demo/GVL_Config/wBatchSize/set\n",
               opt.mqtt_host, opt.mqtt_port);
  }
#endif
  fmt::print("\n");
  print_trace_header();
  std::fflush(stdout);  // the banner now, also into a pipe or a file (a tool waits for the port's line)

  static shift_trace recorder;  // static: 1 MiB is no stack variable
  const bool tracing = opt.vcd_file != nullptr || opt.csv_file != nullptr || opt.svg_file != nullptr;
  if (tracing) {
    add_shift_channels(recorder, plc);
    recorder.set_mode(trace_mode::on_change);
    recorder.attach(plc.task("Fast"));
    recorder.start();
  }

  TRACE_PRG& trace = plc.get<TRACE_PRG>();
  const LTIME slice = "LTIME#100ms"_iec;  // print the trace every 100 ms of machine time
  const auto wall_start = std::chrono::steady_clock::now();
  bool fifo_active = false;
  run_end ended = run_end::time_elapsed;
  if (!opt.realtime) {
    plc.task("Fast").model_execution_time(&sim::fast_cost);
    plc.task("Slow").model_execution_time(&sim::slow_cost);
    while (plc.now() < LTIME(sim::scenario_length) && plc.state() == application_state::running) {
      plc.run_for(slice);
      print_trace(trace);
    }
  } else {
    std::signal(SIGINT, on_sigint);
    realtime_options settings;
    settings.fifo = opt.fifo;
    realtime_runner runner{plc, settings};
    // --watch: a watch list of the shift's values, redrawn by a thread of its own every 500 ms;
    // the task's thread only copies the values after a cycle, every 100 ms.
    watch_list<32> watch{"LTIME#100ms"_iec};
    std::optional<watch_display<32>> display;
    if (opt.watch) {
      add_shift_channels(watch, plc);
      watch.attach(plc.task("Fast"));
      display.emplace(watch, stdout, "LTIME#500ms"_iec, "iecoop demo, task Fast (Ctrl-C stops)");
    }
    const LTIME length = opt.realtime_seconds > 0.0 ? LTIME::from_ticks(static_cast<std::uint64_t>(opt.realtime_seconds * 1e9))
                                                    : LTIME(sim::scenario_length);
    // The runner owns the thread while it runs: run it in slices and print between them.
    for (LTIME done{}; done < length;) {
      const LTIME step = std::min(slice, length - done);
      ended = runner.run(stop_requested, step);
      if (!opt.watch) print_trace(trace);
      if (ended != run_end::time_elapsed) break;
      done += step;
    }
    fifo_active = runner.fifo_active();
    if (display) {
      display.reset();  // the display's thread ends
      watch.detach();
      fmt::print("\n(watched: {} snapshots of task Fast)\n", watch.snapshots());
    }
    std::signal(SIGINT, SIG_DFL);
  }
  const double wall = std::chrono::duration<double>(std::chrono::steady_clock::now() - wall_start).count();

  print_statistics(plc);
  if (!opt.realtime) {
    fmt::print("(simulated: execution times modelled per cycle, Fast 0.2..0.3 ms, Slow 3..4.6 ms, Sim none;\n"
               " --realtime measures them)\n");
  } else {
    fmt::print("(measured; the runner does not preempt: a cycle under way delays the others' start,\n"
               " which shows as their jitter)\n");
  }
  const SUPERVISION_PRG& s = plc.get<SUPERVISION_PRG>();
  fmt::print("\nmachine: parts {}, batches {} (of {}), jams {}, rejected {}, in the open batch {}\n", s.udiParts, s.udiBatches,
             config.wBatchSize, s.uiJams, s.udiRejected, plc.get<GVL>().wParts);
  fmt::print("time:    {:.3f} s of {} time in {:.3f} s of wall-clock time", seconds(plc.now()),
             opt.realtime ? "machine" : "simulated", wall);
  if (!opt.realtime && wall > 0.0) fmt::print(" ({:.0f} x faster)", seconds(plc.now()) / wall);
  fmt::print("\n");
  if (opt.realtime) {
    fmt::print("runner:  {}; SCHED_FIFO {}\n",
               ended == run_end::stop_requested ? "stopped by Ctrl-C"
               : ended == run_end::not_running  ? "ended: the application stopped running"
                                                : "ran its time",
               !opt.fifo ? "not requested (--fifo)" : fifo_active ? "granted" : "refused (needs root or CAP_SYS_NICE)");
  }
  if (plc.state() == application_state::exception && plc.faulted_task() != nullptr) {
    fmt::print("state:   stopped in exception by the watchdog of task {}\n", plc.faulted_task()->name());
  }
  if (tracing) {
    recorder.stop();
    const auto report = [&](const char* path, bool written) {
      if (path == nullptr) return;
      if (written) {
        fmt::print("trace:   {} samples of task Fast ({} bytes each, on change) written to {}\n", recorder.size(),
                   recorder.sample_bytes(), path);
        if (recorder.overwritten() > 0) fmt::print("         (the {} oldest were overwritten)\n", recorder.overwritten());
      } else {
        fmt::print("trace:   could not write {}\n", path);
        ++faults;
      }
    };
    report(opt.vcd_file, opt.vcd_file != nullptr && write_trace(recorder, opt.vcd_file, [](const trace_view& v, auto put) {
                           write_vcd(v, put);
                         }));
    report(opt.csv_file, opt.csv_file != nullptr && write_trace(recorder, opt.csv_file, [](const trace_view& v, auto put) {
                           write_csv(v, put);
                         }));
    report(opt.svg_file, opt.svg_file != nullptr && write_trace(recorder, opt.svg_file, [](const trace_view& v, auto put) {
                           svg_options chart;
                           chart.title = "iecoop demo: the conveyor's shift, task Fast (on change)";
                           write_svg(v, put, chart);
                         }));
  }
#if IECOOP_DEMO_MODBUS
  if (hmi) {
    const modbus_server_statistics served = hmi->statistics();
    fmt::print("modbus:  {} requests served ({} answered with an exception), {} connections\n", served.requests,
               served.exceptions, served.connections);
    hmi->stop();
    plc.connect(sim::field);
  }
#endif
#if IECOOP_DEMO_MQTT
  if (mqtt) {
    mqtt->stop();  // "offline", then disconnect
    const mqtt_bridge_statistics sent = mqtt->statistics();
    fmt::print("mqtt:    {} messages published, {} commands applied ({} rejected), {} connections\n", sent.published,
               sent.commands_applied, sent.commands_rejected, sent.connects);
  }
#endif
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
