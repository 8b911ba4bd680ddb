// What the demo prints: the banner, the trace lines, the tasks' statistics and the summary, with
// fmt and iecoop's formatters for the IEC types (<iecoop/fmt.hpp>; demo.hpp says why this is a
// file of its own).
#include "demo.hpp"

#include <iecoop/fmt.hpp>

#include <fmt/core.h>

#include <string>

namespace demo_host {
namespace {

using namespace iecoop;

double seconds(LTIME t) { return static_cast<double>(t.count()) / 1e9; }
double millis(LTIME t) { return static_cast<double>(t.count()) / 1e6; }
const char* bit(BOOL b) { return b ? "1" : "."; }

}  // namespace

void print_trace_header() {
  fmt::print("\nTrace: a line when the operator acts or a key signal changes. parts: the conveyor's CTU\n"
             "(task Fast); total: SUPERVISION_PRG's RETAIN counter (task Slow, every 20 ms); speed: the\n"
             "drive's PROPERTY rSpeed, % of nominal.\n\n");
  fmt::print("{:>6}  {:-^24}   {:-^16}   {:-^17}\n", "", " inputs ", " outputs ", " PLC ");
  fmt::print("{:>6}  {:>5} {:>4} {:>3} {:>5} {:>3} | {:>5} {:>4} {:>5} | {:>5} {:>5} {:>5} | {}\n", "time s", "START",
             "STOP", "EYE", "RESET", "IW1", "MOTOR", "LAMP", "QW1", "speed", "parts", "total", "event");
}

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

namespace {

void print_statistics(const conveyor_app& plc) {
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

}  // namespace

void print_banner(conveyor_app& plc, bool realtime, const char* retain_file) {
  using namespace demo;
  const GVL_Config& config = plc.get<GVL_Config>();
  const bool dol = config.eMotor == E_Motor::DOL;
  fmt::print("iecoop {}.{}.{} demo: a conveyor with a jam timeout, {}\n\n", IECOOP_VERSION_MAJOR, IECOOP_VERSION_MINOR,
             IECOOP_VERSION_PATCH, realtime ? "in real time" : "in simulated time");
  fmt::print("  inputs   %IX0.0 START (NO)  %IX0.1 STOP (NC)  %IX0.2 photo eye  %IX0.3 RESET  %IW1 speed %\n");
  fmt::print("  outputs  %QX0.0 {}  %QX0.1 jam lamp  %QW1 speed reference (16#4000 = 100 %)\n",
             dol ? "contactor" : "drive enable");
  fmt::print("  drive    {}, batches of {} parts, jam after T#2s at the eye\n",
             dol ? "DOL (FB_DolMotor: on or off, 100 %)" : "VFD (FB_VfdMotor: ramp T#1s, 20..100 %)", config.wBatchSize);
  fmt::print("  tasks    Sim 1 ms (operator, belt, trace)  Fast 1 ms: IO_PRG  Slow 20 ms: SUPERVISION_PRG\n");
  if (retain_file != nullptr) {
    const SUPERVISION_PRG& s = plc.get<SUPERVISION_PRG>();
    fmt::print("  retain   {}: parts {}, jams {} from the runs before\n", retain_file, s.udiParts, s.uiJams);
  }
}

void print_summary(conveyor_app& plc, const run_summary& run) {
  using namespace demo;
  print_statistics(plc);
  if (!run.realtime) {
    fmt::print("(simulated: execution times modelled per cycle, Fast 0.2..0.3 ms, Slow 3..4.6 ms, Sim none;\n"
               " --realtime measures them)\n");
  } else {
    fmt::print("(measured; the runner does not preempt: a cycle under way delays the others' start,\n"
               " which shows as their jitter)\n");
  }
  const SUPERVISION_PRG& s = plc.get<SUPERVISION_PRG>();
  fmt::print("\nmachine: parts {}, batches {} (of {}), jams {}, rejected {}, in the open batch {}\n", s.udiParts, s.udiBatches,
             plc.get<GVL_Config>().wBatchSize, s.uiJams, s.udiRejected, plc.get<GVL>().wParts);
  fmt::print("time:    {:.3f} s of {} time in {:.3f} s of wall-clock time", seconds(plc.now()),
             run.realtime ? "machine" : "simulated", run.wall_seconds);
  if (!run.realtime && run.wall_seconds > 0.0) fmt::print(" ({:.0f} x faster)", seconds(plc.now()) / run.wall_seconds);
  fmt::print("\n");
  if (run.realtime) {
    fmt::print("runner:  {}; SCHED_FIFO {}\n", run.ended,
               !run.fifo_requested ? "not requested (--fifo)"
               : run.fifo_active   ? "granted"
                                   : "refused (needs root or CAP_SYS_NICE)");
  }
  if (plc.state() == application_state::exception && plc.faulted_task() != nullptr) {
    fmt::print("state:   stopped in exception by the watchdog of task {}\n", plc.faulted_task()->name());
  }
}

bool print_trace_file(const shift_trace& trace, const char* path, bool written) {
  if (!written) {
    fmt::print("trace:   could not write {}\n", path);
    return false;
  }
  fmt::print("trace:   {} samples of task Fast ({} bytes each, on change) written to {}\n", trace.size(), trace.sample_bytes(),
             path);
  if (trace.overwritten() > 0) fmt::print("         (the {} oldest were overwritten)\n", trace.overwritten());
  return true;
}

}  // namespace demo_host
