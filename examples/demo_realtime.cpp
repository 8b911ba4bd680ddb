// The demo in real time (--realtime): the application on iecoop's real-time runner against the
// wall clock, Ctrl-C to stop, and with --watch a watch list redrawn by a thread of its own
// (demo.hpp says why this is a file of its own).
#include "demo.hpp"

#include <iecoop/runtime/realtime.hpp>
#include <iecoop/trace/watch.hpp>

#include <fmt/core.h>

#include <algorithm>
#include <atomic>
#include <csignal>
#include <cstdint>
#include <cstdio>
#include <optional>

namespace demo_host {
namespace {

using namespace iecoop;

// Ctrl-C: the runner looks at this flag at least every 50 ms and returns.
std::atomic<bool> stop_requested{false};
static_assert(std::atomic<bool>::is_always_lock_free);
void on_sigint(int) { stop_requested.store(true); }

}  // namespace

realtime_result run_realtime(conveyor_app& plc, const realtime_request& request, void (*print_trace)(sim::TRACE_PRG&)) {
  std::signal(SIGINT, on_sigint);
  realtime_options settings;
  settings.fifo = request.fifo;
  realtime_runner runner{plc, settings};
  // --watch: a watch list of the shift's values, redrawn by a thread of its own every 500 ms;
  // the task's thread only copies the values after a cycle, every 100 ms.
  watch_list<32> watch{"LTIME#100ms"_iec};
  std::optional<watch_display<32>> display;
  if (request.watch) {
    add_shift_channels(watch, plc);
    watch.attach(plc.task("Fast"));
    display.emplace(watch, stdout, "LTIME#500ms"_iec, "iecoop demo, task Fast (Ctrl-C stops)");
  }
  const LTIME length = request.seconds > 0.0 ? LTIME::from_ticks(static_cast<std::uint64_t>(request.seconds * 1e9))
                                             : LTIME(sim::scenario_length);
  const LTIME slice = "LTIME#100ms"_iec;  // print the trace every 100 ms of machine time
  sim::TRACE_PRG& trace = plc.get<sim::TRACE_PRG>();
  run_end ended = run_end::time_elapsed;
  // The runner owns the thread while it runs: run it in slices and print between them.
  for (LTIME done{}; done < length;) {
    const LTIME step = std::min(slice, length - done);
    ended = runner.run(stop_requested, step);
    if (!request.watch) print_trace(trace);
    if (ended != run_end::time_elapsed) break;
    done += step;
  }
  realtime_result result;
  result.fifo_active = runner.fifo_active();
  result.ended = ended == run_end::stop_requested ? "stopped by Ctrl-C"
                 : ended == run_end::not_running  ? "ended: the application stopped running"
                                                  : "ran its time";
  if (display) {
    display.reset();  // the display's thread ends
    watch.detach();
    fmt::print("\n(watched: {} snapshots of task Fast)\n", watch.snapshots());
  }
  std::signal(SIGINT, SIG_DFL);
  return result;
}

}  // namespace demo_host
