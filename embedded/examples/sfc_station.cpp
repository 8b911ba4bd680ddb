// Firmware example: a fill / heat / hold / drain station written as an SFC chart (sfc::chart,
// CODESYS's scan order), in a PROGRAM called every 10 ms with the cycle clock set before each
// call as a task would.
//
//   IDLE --START--> FILL --LEVEL >= 80--> HEAT --TEMP >= 70--> HOLD --HOLD.T >= T#500ms-->
//   DRAIN --LEVEL <= 0--> IDLE
//
// FILL opens the inlet (VALVE_IN, N) and starts the mixer (MIXER, S); HEAT switches the heater
// on (HEATER, N) with a booster for its first 100 ms (BOOST, L) and runs the ACTION A_HEAT_LOG
// (N); DRAIN opens the outlet (VALVE_OUT, N) and stops the mixer (MIXER, R). The tank is
// simulated by main(): the inlet adds 4 % of level a cycle, the outlet takes 5 %, the heater
// adds 1 degree a cycle and the booster 2 more; an empty tank is back at 20 degrees. An operator
// presses START at 100 ms and at 3 s. main() prints when each step became active and what
// the actions did, and checks it.
#include <cstdint>
#include <string_view>

#include <iecoop/iecoop.hpp>

#include "console.hpp"
#include "exit_status.hpp"
#include "fault_handler.hpp"
#include "scan_cost.hpp"

namespace {

using namespace iecoop;

// PROGRAM STATION
struct STATION : program<STATION> {
  // VAR_INPUT
  BOOL START;  // START : BOOL;
  INT LEVEL;   // LEVEL : INT;   (%)
  INT TEMP;    // TEMP : INT;    (degrees)
  // VAR_OUTPUT
  BOOL VALVE_IN;   // VALVE_IN : BOOL;
  BOOL MIXER;      // MIXER : BOOL;
  BOOL HEATER;     // HEATER : BOOL;
  BOOL BOOST;      // BOOST : BOOL;
  BOOL VALVE_OUT;  // VALVE_OUT : BOOL;
  // VAR
  INT nHeatLog;  // nHeatLog : INT;   scans A_HEAT_LOG ran in
  TIME tHeated;  // tHeated : TIME;   HEAT.T as A_HEAT_LOG last saw it
  // END_VAR
  sfc::step IDLE, FILL, HEAT, HOLD, DRAIN;

  // ACTION A_HEAT_LOG: nHeatLog := nHeatLog + 1; tHeated := HEAT.T; END_ACTION
  void A_HEAT_LOG() {
    nHeatLog = nHeatLog + 1;
    tHeated = HEAT.T;
  }
  // TRANSITION FROM FILL TO HEAT := LEVEL >= 80; END_TRANSITION (and the others: named objects)
  BOOL T_FULL() { return LEVEL >= 80; }
  BOOL T_HOT() { return TEMP >= 70; }
  BOOL T_HELD() { return HOLD.T >= "T#500ms"_iec; }
  BOOL T_EMPTY() { return LEVEL <= 0; }

  using P = STATION;
  // clang-format off: one chart element a line, as textual SFC writes them
  sfc::chart<P,
             sfc::INITIAL_STEP<&P::IDLE>,  // INITIAL_STEP IDLE: END_STEP
             sfc::TRANSITION<sfc::FROM<&P::IDLE>, sfc::TO<&P::FILL>, &P::START>,
             sfc::STEP<&P::FILL, sfc::N<&P::VALVE_IN>, sfc::S<&P::MIXER>>,  // VALVE_IN(N); MIXER(S);
             sfc::TRANSITION<sfc::FROM<&P::FILL>, sfc::TO<&P::HEAT>, &P::T_FULL>,
             sfc::STEP<&P::HEAT, sfc::N<&P::HEATER>, sfc::L<&P::BOOST, "T#100ms">,  // HEATER(N); BOOST(L, T#100ms);
                       sfc::N<&P::A_HEAT_LOG>>,                                     // A_HEAT_LOG(N);
             sfc::TRANSITION<sfc::FROM<&P::HEAT>, sfc::TO<&P::HOLD>, &P::T_HOT>, sfc::STEP<&P::HOLD>,
             sfc::TRANSITION<sfc::FROM<&P::HOLD>, sfc::TO<&P::DRAIN>, &P::T_HELD>,
             sfc::STEP<&P::DRAIN, sfc::N<&P::VALVE_OUT>, sfc::R<&P::MIXER>>,  // VALVE_OUT(N); MIXER(R);
             sfc::TRANSITION<sfc::FROM<&P::DRAIN>, sfc::TO<&P::IDLE>, &P::T_EMPTY>>
      chart;
  // clang-format on

  void body() { chart(*this); }
};
// END_PROGRAM

STATION station;

// The tank: what the outputs of the last cycle did to it.
struct tank {
  int level = 0;
  int temp = 20;
  void step(const STATION& s) {
    if (s.VALVE_IN) level += 4;
    if (s.VALVE_OUT) level -= 5;
    if (level > 100) level = 100;
    if (level < 0) level = 0;
    if (s.HEATER) temp += 1;
    if (s.BOOST) temp += 2;
    if (level == 0) temp = 20;
  }
};

// How many cycles a BOOL output was TRUE in.
struct on_count {
  int cycles = 0;
  void record(BOOL on) {
    if (on) ++cycles;
  }
};

}  // namespace

int main() {
  firmware::install_fault_handler();
  firmware::scan_cost::start();  // only a build with IECOOP_FIRMWARE_SCAN_COST measures (scan_cost.hpp)
  using chart_type = decltype(station.chart);
  constexpr auto members = chart_type::step_members();
  constexpr auto names = chart_type::step_names();
  bool was_active[members.size()] = {};
  tank plant;
  on_count heater, boost, mixer;
  int batches = 0, entries = 0;
  long last_entry = -1;
  for (long t = 0; t <= 6000; t += 10) {
    // The cycle: the time stamp of its start, the inputs, the program.
    cycle_clock::set(LTIME::from_ticks(static_cast<std::uint64_t>(t) * 1000000U));  // ms in ns
    station.START = (t >= 100 && t < 150) || (t >= 3000 && t < 3050);
    station.LEVEL = INT(static_cast<std::int16_t>(plant.level));
    station.TEMP = INT(static_cast<std::int16_t>(plant.temp));
    firmware::scan_cost::begin();
    station();
    firmware::scan_cost::end();
    plant.step(station);
    heater.record(station.HEATER);
    boost.record(station.BOOST);
    mixer.record(station.MIXER);
    for (std::size_t i = 0; i < members.size(); ++i) {
      const bool active = (station.*members[i]).X;
      if (active && !was_active[i]) {
        firmware::print_line(t, " ms ", names[i]);
        ++entries;
        last_entry = t;
        if (names[i] == std::string_view("DRAIN")) ++batches;
      }
      was_active[i] = active;
    }
  }
  firmware::print_line("batches ", batches, ", heater on ", heater.cycles, " cycles, boost ", boost.cycles,
                       " cycles, mixer ", mixer.cycles, " cycles");
  firmware::print_line("A_HEAT_LOG ran ", station.nHeatLog, " scans, last saw HEAT.T = ", station.tHeated);
  firmware::print_line("SFCCurrentStep = ", station.chart.SFCCurrentStep.get().view());
  // Two batches of five steps each, after IDLE at the start; the second ends at 4220 ms. Each
  // HEAT lasts 31 cycles: 10 boosted (+3 degrees) from 20 to 50 degrees, 20 more (+1) to 70, and
  // the one whose transition sees 70 (the heater is on in it: the actions run first). A_HEAT_LOG
  // runs one scan more than the heater: its final scan, the cycle after HEAT was left, where
  // HEAT.T keeps its last value. The mixer runs from FILL's first cycle to DRAIN's first.
  const bool ok = batches == 2 && entries == 11 && last_entry == 4220 && boost.cycles == 20 && heater.cycles == 62 &&
                  mixer.cycles == 206 && station.nHeatLog == 64 && station.tHeated == "T#300ms"_iec && !station.MIXER &&
                  station.IDLE.X;
  firmware::scan_cost::report("sfc_station");
  firmware::print_line("RESULT sfc_station ", ok ? "PASS" : "FAIL");
  return ok ? firmware::exit_status::passed : firmware::exit_status::failed;
}
