// What the trace benchmarks record (trace_bench.cpp, count_main.cpp): a program of 16 BOOLs and
// 8 INTs that all change every cycle, as a program's variables do, and a trace_recorder with
// one channel for each of them, sampled after each cycle.
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <string_view>

#include <iecoop/iecoop.hpp>
#include <iecoop/trace.hpp>

namespace trace_programs {

using namespace iecoop;

// PROGRAM SIGNALS_PRG
struct SIGNALS_PRG : program<SIGNALS_PRG> {
  // VAR
  UDINT nCycle;             // nCycle : UDINT;
  std::array<BOOL, 16> x;   // x : ARRAY[0..15] OF BOOL;
  std::array<INT, 8> iVal;  // iVal : ARRAY[0..7] OF INT;
  BOOL bNever;              // bNever : BOOL;   (a trigger that does not fire)
  // END_VAR

  void body() {
    nCycle = nCycle + 1U;  // nCycle := nCycle + 1;
    const std::uint32_t k = nCycle.value();
    for (std::size_t i = 0; i < x.size(); ++i) {  // FOR i := 0 TO 15 DO
      x[i] = ((k >> i) & 1U) != 0;                //   x[i] := bit i of nCycle;  (x[0] changes every cycle)
    }
    for (std::size_t i = 0; i < iVal.size(); ++i) {           // FOR i := 0 TO 7 DO
      iVal[i] = INT(static_cast<std::int16_t>(k * (i + 1)));  //   iVal[i] := nCycle * (i + 1);
    }
  }
};

inline constexpr std::array<std::string_view, 16> bool_names = {"x0", "x1", "x2",  "x3",  "x4",  "x5",  "x6",  "x7",
                                                                "x8", "x9", "x10", "x11", "x12", "x13", "x14", "x15"};
inline constexpr std::array<std::string_view, 8> int_names = {"iVal0", "iVal1", "iVal2", "iVal3",
                                                              "iVal4", "iVal5", "iVal6", "iVal7"};

/// The 24 channels: SIGNALS_PRG.x0 .. x15, SIGNALS_PRG.iVal0 .. iVal7.
template <class Recorder>
void add_channels(Recorder& trace, const SIGNALS_PRG& prg) {
  for (std::size_t i = 0; i < bool_names.size(); ++i) trace.add("SIGNALS_PRG", bool_names[i], prg.x[i]);
  for (std::size_t i = 0; i < int_names.size(); ++i) trace.add("SIGNALS_PRG", int_names[i], prg.iVal[i]);
}

/// How a benchmark records.
enum class recording : std::uint8_t {
  none,                       ///< the program alone (the baseline)
  every_cycle,                ///< trace_mode::every_cycle
  every_cycle_trigger_armed,  ///< every cycle, waiting for a trigger on bNever (pre-trigger 100)
  on_change,                  ///< trace_mode::on_change; something changes every cycle: every sample stored
  on_change_unchanged,        ///< trace_mode::on_change with the program not called: no sample stored
};

/// The program and a recorder of 64 KiB of samples, stepped one cycle at a time, as a 1 ms
/// task would: the program, then the sample at the cycle's start time.
struct traced_program {
  SIGNALS_PRG prg;
  trace_recorder<64 * 1024, 32> trace;
  recording how;
  std::uint64_t cycle = 0;

  explicit traced_program(recording r) : how(r) {
    add_channels(trace, prg);
    if (how == recording::on_change || how == recording::on_change_unchanged) trace.set_mode(trace_mode::on_change);
    if (how == recording::every_cycle_trigger_armed) trace.trigger_on(prg.bNever, trace_edge::rising, 100);
    if (how != recording::none) trace.start();
  }
  traced_program(const traced_program&) = delete;
  traced_program& operator=(const traced_program&) = delete;

  void run_cycle() {
    const LTIME start = LTIME::from_ticks(cycle * 1'000'000);
    if (how != recording::on_change_unchanged) prg();
    if (how != recording::none) trace.sample(start, cycle);
    ++cycle;
  }
};

}  // namespace trace_programs
