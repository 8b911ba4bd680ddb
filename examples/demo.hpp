// What the demo's three translation units share: the application's type, the trace of the shift
// and the values it records, and what each of the other two files offers demo.cpp.
//
//   demo.cpp           the command line, the run in simulated time
//   demo_print.cpp     what it prints: the banner, the trace lines, the statistics, the summary
//   demo_realtime.cpp  the run in real time: the real-time runner, the watch list (threads)
//   demo_trace.cpp     the trace written as VCD, CSV and SVG files
//   demo_exchange.cpp  the Modbus TCP server and the MQTT bridge (--modbus, --mqtt)
//
// The PLC program is conveyor.hpp. The host's parts sit in files of their own, as a project would
// keep them: each file pays only for the headers and the code it uses, an edit of one compiles
// that one again, and the five compile side by side (docs/performance.md, "Compile time").
#pragma once

#include "conveyor.hpp"

#include <iecoop/iecoop.hpp>

#include <cstdint>
#include <string>

namespace demo_host {

/// The application of conveyor.hpp: its tasks, programs and global variable lists.
using conveyor_app = decltype(demo::make_conveyor());

/// The trace of the shift (CODESYS Trace on task Fast, record condition "on change"): the I/O,
/// the conveyor's jam timer, the speed setpoint (a PROPERTY), the speed and the part counts.
/// 1 MiB holds the whole 21 s shift; written with --vcd, --csv, --svg after the run.
using shift_trace = iecoop::trace_recorder<1024 * 1024, 32>;

/// The values the trace records, the watch list shows and the MQTT bridge publishes.
template <class Channels>
void add_shift_channels(Channels& channels, conveyor_app& plc) {
  using namespace demo;
  const IO_PRG& io = plc.get<IO_PRG>();
  const GVL& gvl = plc.get<GVL>();
  channels.add_located("GVL_IO", plc.get<GVL_IO>());                  // the 8 located variables
  channels.add_pins("IO_PRG.fbConveyor.tJam", io.fbConveyor.tJam);    // IN, PT, Q, ET
  channels.add("IO_PRG.fbConveyor", "rSpeed", io.fbConveyor.rSpeed);  // PROPERTY: the setpoint
  channels.add("GVL", "rSpeed", gvl.rSpeed);                          // the speed now
  channels.add("GVL", "bAtSpeed", gvl.bAtSpeed);
  channels.add("GVL", "wParts", gvl.wParts);
  channels.add("SUPERVISION_PRG", "udiParts", plc.get<SUPERVISION_PRG>().udiParts);
}

// --- demo_print.cpp ----------------------------------------------------------------------

/// The machine, its I/O, the drive, the tasks and, with --retain, what the runs before left.
void print_banner(conveyor_app& plc, bool realtime, const char* retain_file);
/// The head of the trace's table, then print_trace() its lines recorded since the last call.
void print_trace_header();
void print_trace(sim::TRACE_PRG& trace);
/// How the run went, for the summary.
struct run_summary {
  bool realtime = false;
  double wall_seconds = 0.0;
  const char* ended = "ran its time";  // --realtime: how the runner ended (realtime_result)
  bool fifo_requested = false;
  bool fifo_active = false;
};
/// The tasks' statistics, the machine's counts, machine and wall-clock time.
void print_summary(conveyor_app& plc, const run_summary& run);
/// The line of a trace file `written` (or not) to `path`; returns `written`.
bool print_trace_file(const shift_trace& trace, const char* path, bool written);

// --- demo_realtime.cpp -------------------------------------------------------------------

/// What the command line asks of the run in real time.
struct realtime_request {
  double seconds = 0.0;  // --realtime SECONDS; 0: the whole scenario
  bool fifo = false;     // --fifo
  bool watch = false;    // --watch: a watch list redrawn every 500 ms instead of the trace lines
};
struct realtime_result {
  const char* ended = "ran its time";  // or "stopped by Ctrl-C", "ended: the application stopped running"
  bool fifo_active = false;            // SCHED_FIFO granted
};

/// Runs `plc` on the real-time runner for the time asked (Ctrl-C stops it), calling
/// `print_trace` every 100 ms of it unless the watch list is shown.
realtime_result run_realtime(conveyor_app& plc, const realtime_request& request, void (*print_trace)(sim::TRACE_PRG&));

// --- demo_trace.cpp ----------------------------------------------------------------------

/// Each writes the trace to `path`; FALSE if the file could not be written.
bool write_vcd_file(const shift_trace& trace, const char* path);
bool write_csv_file(const shift_trace& trace, const char* path);
bool write_svg_file(const shift_trace& trace, const char* path);

// --- demo_exchange.cpp -------------------------------------------------------------------

/// Whether this build has the Modbus server (libmodbus) and the MQTT bridge (libmosquitto).
extern const bool built_with_modbus;
extern const bool built_with_mqtt;

/// What the command line asks of the network.
struct exchange_options {
  int modbus_port = -1;  // --modbus PORT (0: a free one); -1: no server
  std::string mqtt_host;  // --mqtt HOST[:PORT]; empty: no bridge
  std::uint16_t mqtt_port = 1883;
};

/// Starts the Modbus server and the MQTT bridge the options ask for, connected to `plc`, and
/// prints a line for each; FALSE (the error printed) if one could not start. Either way,
/// stop_exchange() ends what was started before the application goes.
bool start_exchange(conveyor_app& plc, const exchange_options& options);
/// Prints what they did, stops them and connects `plc` to the simulated field again.
void stop_exchange(conveyor_app& plc);

}  // namespace demo_host
